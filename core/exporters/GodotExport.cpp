// GodotExport; see GodotExport.h and docs/export.md for the conversion.
#include "core/exporters/GodotExport.h"

#include "core/base/AtomicFile.h"
#include "core/exporters/EngineConversion.h"
#include "core/exporters/EnginePreview.h"
#include "core/exporters/PackageExport.h"
#include "core/image/ImageIO.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace relief::core::inline exporters {
namespace {

std::string number(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  std::string text = buffer;
  // Godot writes floats with a decimal point.
  if (text.find_first_of(".e") == std::string::npos)
    text += ".0";
  return text;
}

const char* boolean(bool value) {
  return value ? "true" : "false";
}

struct GodotTexture {
  std::string id;  // "<n>_<suffix>", the .tres's ext_resource id
  std::string file;
};

// The id of the texture written with `suffix`, or empty.
std::string textureIdOf(const std::vector<GodotTexture>& textures, const std::string& suffix) {
  for (const GodotTexture& t : textures) {
    if (t.id.size() > suffix.size() && t.id.substr(t.id.size() - suffix.size()) == suffix)
      return t.id;
  }
  return {};
}

// Writes the material's maps as PNGs beside the .tres, in the order the .tres lists them.
Status writeGodotTextures(const Material& material, const std::filesystem::path& directory,
                          const std::string& stem, bool parallax,
                          std::vector<GodotTexture>& textures) {
  const auto addTexture = [&](const Image& image, const std::string& suffix,
                              SampleFormat format) -> Status {
    const std::string file = stem + "_" + suffix + ".png";
    if (Status saved = saveImage(image, (directory / file).string(), format); !saved)
      return saved;
    textures.push_back({std::to_string(textures.size() + 1) + "_" + suffix, file});
    return {};
  };
  if (const Image* color = material.image(MapSlot::Color)) {
    if (Status s = addTexture(*color, "albedo", SampleFormat::UInt8); !s)
      return s;
  }
  if (const Image* normals = material.image(MapSlot::Normal)) {
    // Godot reads normal maps as X+ Y+ Z+ (OpenGL).
    const Image converted = openGlNormalMap(*normals, material.parameterFlag(ParamId::NormalYDown));
    if (Status s = addTexture(converted, "normal", SampleFormat::UInt8); !s)
      return s;
  }
  if (parallax) {
    if (Status s = addTexture(*material.image(MapSlot::Height), "height", SampleFormat::UInt16); !s)
      return s;
  }
  if (const Image* occlusion = material.image(MapSlot::AmbientOcclusion)) {
    if (Status s = addTexture(*occlusion, "ao", SampleFormat::UInt8); !s)
      return s;
  }
  if (const Image* roughness = material.image(MapSlot::Roughness)) {
    if (Status s = addTexture(*roughness, "roughness", SampleFormat::UInt8); !s)
      return s;
  }
  if (const Image* metallic = material.image(MapSlot::Metallic)) {
    if (Status s = addTexture(*metallic, "metallic", SampleFormat::UInt8); !s)
      return s;
  }
  return {};
}

// StandardMaterial3D's heightmap properties converted from Relief's, and what Godot cannot show.
void writeGodotHeightmap(std::ostream& tres, const Material& material, const std::string& heightId,
                         std::vector<std::string>& notes) {
  const double scale = material.parameter(ParamId::HeightScale);
  const double bias = material.parameter(ParamId::HeightBias);
  const GodotHeightmap heightmap = godotHeightmap(material);
  const bool deep = heightmap.deepParallax;
  tres << "heightmap_enabled = true\n";
  tres << "heightmap_scale = " << number(heightmap.scale) << "\n";
  tres << "heightmap_deep_parallax = " << boolean(deep) << "\n";
  if (deep) {
    tres << "heightmap_min_layers = " << heightmap.minLayers << "\n";
    tres << "heightmap_max_layers = " << heightmap.maxLayers << "\n";
  }
  tres << "heightmap_flip_tangent = false\n";
  tres << "heightmap_flip_binormal = false\n";
  tres << "heightmap_flip_texture = " << boolean(heightmap.flipTexture) << "\n";
  tres << "heightmap_texture = ExtResource(\"" << heightId << "\")\n";
  if (std::abs(bias + scale) > 1e-6) {
    notes.push_back("Godot puts the top of the relief on the surface; heightBias " + number(bias) +
                    " (not -heightScale) has no Godot equivalent");
  }
  if (material.technique() == Technique::Parallax) {
    notes.push_back(
        "Godot has no unlimited (Kaneko) parallax; its offset-limited "
        "parallax is used");
  }
  if (deep) {
    notes.push_back(
        "Godot's deep parallax limits the offset like Welsh's (view.xy, not "
        "view.xy / view.z): at grazing angles the relief looks shallower "
        "than in Relief");
  }
}

}  // namespace

Result<EngineExportResult> exportGodot(const Preset& preset, const std::string& folder) {
  if (Status made = makeExportFolder(folder); !made)
    return makeError(made.error());
  const Material& material = preset.material;
  const std::string stem = exportStem(material);
  const std::filesystem::path directory(folder);
  EngineExportResult result;
  const bool parallax =
      material.technique() != Technique::Normal && material.hasMap(MapSlot::Height);
  std::vector<GodotTexture> textures;
  if (Status written = writeGodotTextures(material, directory, stem, parallax, textures); !written)
    return makeError(written.error());
  const auto idOf = [&textures](const std::string& suffix) {
    return textureIdOf(textures, suffix);
  };

  std::ostringstream tres;
  tres << "[gd_resource type=\"StandardMaterial3D\" load_steps=" << textures.size() + 1
       << " format=3]\n\n";
  for (const GodotTexture& t : textures) {
    tres << "[ext_resource type=\"Texture2D\" path=\"" << t.file << "\" id=\"" << t.id << "\"]\n";
  }
  tres << "\n[resource]\n";
  tres << "resource_name = \"" << stem << "\"\n";
  if (!idOf("albedo").empty())
    tres << "albedo_texture = ExtResource(\"" << idOf("albedo") << "\")\n";
  // Godot multiplies roughness_texture by roughness and metallic_texture by metallic (each
  // read from its red channel by default), as the viewport does under pbr.
  tres << "metallic = " << number(exportedMetallic(material)) << "\n";
  tres << "roughness = " << number(exportedRoughness(material)) << "\n";
  if (!idOf("roughness").empty()) {
    tres << "roughness_texture = ExtResource(\"" << idOf("roughness") << "\")\n";
  }
  if (!idOf("metallic").empty())
    tres << "metallic_texture = ExtResource(\"" << idOf("metallic") << "\")\n";
  if (!idOf("normal").empty()) {
    tres << "normal_enabled = true\n";
    tres << "normal_scale = " << number(material.parameter(ParamId::NormalStrength)) << "\n";
    tres << "normal_texture = ExtResource(\"" << idOf("normal") << "\")\n";
  }
  if (!idOf("ao").empty()) {
    tres << "ao_enabled = true\n";
    tres << "ao_texture = ExtResource(\"" << idOf("ao") << "\")\n";
  }
  if (parallax)
    writeGodotHeightmap(tres, material, idOf("height"), result.notes);
  for (std::string& loss : engineLosses(material, Engine::Godot))
    result.notes.push_back(std::move(loss));
  const double tiling = material.parameter(ParamId::Tiling);
  tres << "uv1_scale = Vector3(" << number(tiling) << ", " << number(tiling) << ", 1.0)\n";

  result.mainPath = (directory / (stem + ".tres")).string();
  if (Status written = writeFileAtomically(result.mainPath, tres.str()); !written) {
    return makeError(written.error());
  }
  return result;
}

}  // namespace relief::core::inline exporters
