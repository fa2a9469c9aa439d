// UnrealExport; see UnrealExport.h and docs/export.md for the conversion.
#include "core/exporters/UnrealExport.h"

#include "core/base/AtomicFile.h"
#include "core/exporters/PackageExport.h"
#include "core/image/ImageIO.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace relief::core::inline exporters {
namespace {

// Where Unreal keeps Epic's POM function, and the names of its inputs the manifest wires.
constexpr const char* kPomFunction =
    "/Engine/Functions/Engine_MaterialFunctions01/Texturing/ParallaxOcclusionMapping";

QString qs(const std::string& text) {
  return QString::fromStdString(text);
}

// The manifest's "parallax": Epic's POM function and its inputs converted from Relief's, and
// what the conversion cannot keep.
QJsonObject unrealParallax(const Material& material, std::vector<std::string>& notes) {
  const double scale = material.parameter(ParamId::HeightScale);
  const double bias = material.parameter(ParamId::HeightBias);
  const bool deep = isOccludingRelief(material.technique());
  const UnrealPom pom = unrealPom(material);
  QJsonObject parallax{
      {QStringLiteral("function"), QString::fromLatin1(kPomFunction)},
      {QStringLiteral("HeightRatio"), pom.heightRatio},
      {QStringLiteral("MinSteps"), pom.minSteps},
      {QStringLiteral("MaxSteps"), pom.maxSteps},
      {QStringLiteral("ReferencePlane"), pom.referencePlane},
      {QStringLiteral("HeightmapChannel"), QJsonArray{1, 0, 0, 0}},
      {QStringLiteral("PixelDepthOffset"), pom.pixelDepthOffset},
      {QStringLiteral("inputs"),
       QJsonObject{{QStringLiteral("HeightRatio"), QStringLiteral("Height Ratio")},
                   {QStringLiteral("MinSteps"), QStringLiteral("Min Steps")},
                   {QStringLiteral("MaxSteps"), QStringLiteral("Max Steps")},
                   {QStringLiteral("ReferencePlane"), QStringLiteral("Reference Plane")}}},
      {QStringLiteral("outputs"), QStringLiteral("Parallax UVs drive every texture's UVs; "
                                                 "Pixel Depth Offset when PixelDepthOffset")},
  };
  if (!deep) {
    notes.push_back(
        "Unreal's parallax is the POM function; Relief's single-step parallax is exported as "
        "one step of it");
  }
  const double plane = -bias / std::max(scale, 1e-12);
  if (plane < 0.0 || plane > 1.0) {
    notes.push_back("heightBias " + engineNumber(bias) +
                    " puts the surface outside the relief; Reference Plane clamped to " +
                    engineNumber(pom.referencePlane));
  }
  return parallax;
}

// The import script is compiled in (core/exporters/scripts); the manifest's name goes first.
Status writeImportScript(const std::filesystem::path& directory, const std::string& stem,
                         const std::string& manifestFile) {
  QFile script(QStringLiteral(":/exporters/unreal_import.py"));
  if (!script.open(QIODevice::ReadOnly))
    return makeError("the Unreal import script is missing from this build");
  const std::string text =
      "MANIFEST = \"" + manifestFile + "\"  # written by Relief\n" + script.readAll().toStdString();
  return writeFileAtomically((directory / (stem + "_unreal_import.py")).string(), text);
}

}  // namespace

Result<EngineExportResult> exportUnreal(const Preset& preset, const std::string& folder) {
  if (Status made = makeExportFolder(folder); !made)
    return makeError(made.error());
  const Material& material = preset.material;
  const std::string stem = exportStem(material);
  const std::filesystem::path directory(folder);
  EngineExportResult result;

  QJsonObject textures;
  // compression: Unreal's TextureCompressionSettings by name, as its Python API spells them.
  const auto write = [&](const std::string& key, const Image& image, SampleFormat format, bool srgb,
                         const char* compression, QJsonObject extra = {}) -> Status {
    const std::string file = "T_" + stem + "_" + key + ".png";
    if (Status saved = saveImage(image, (directory / file).string(), format); !saved)
      return saved;
    extra.insert(QStringLiteral("file"), qs(file));
    extra.insert(QStringLiteral("srgb"), srgb);
    extra.insert(QStringLiteral("compression"), QString::fromLatin1(compression));
    textures.insert(qs(key), extra);
    return {};
  };

  if (const Image* color = material.image(MapSlot::Color)) {
    if (Status s = write("BaseColor", *color, SampleFormat::UInt8, true, "TC_DEFAULT"); !s)
      return makeError(s.error());
  }
  if (const Image* normals = material.image(MapSlot::Normal)) {
    // Unreal's normal maps are green-down (DirectX).
    const Image converted =
        directXNormalMap(*normals, material.parameterFlag(ParamId::NormalYDown));
    if (Status s = write("Normal", converted, SampleFormat::UInt8, false, "TC_NORMALMAP",
                         {{QStringLiteral("convention"), QStringLiteral("DirectX, green down")}});
        !s) {
      return makeError(s.error());
    }
  }
  const double roughness = exportedRoughness(material);
  QJsonObject constants;
  if (const std::optional<Image> orm = packEngineMasks(material, "orm")) {
    const QJsonObject channels{{QStringLiteral("r"), QStringLiteral("ambient occlusion")},
                               {QStringLiteral("g"), QStringLiteral("roughness")},
                               {QStringLiteral("b"), QStringLiteral("metallic")}};
    if (Status s = write("ORM", *orm, SampleFormat::UInt8, false, "TC_MASKS",
                         {{QStringLiteral("channels"), channels}});
        !s) {
      return makeError(s.error());
    }
  } else {
    constants.insert(QStringLiteral("Roughness"), roughness);
    constants.insert(QStringLiteral("Metallic"), exportedMetallic(material));
  }

  QJsonObject root{
      {QStringLiteral("format"), QStringLiteral("relief-unreal-material")},
      {QStringLiteral("version"), 1},
      {QStringLiteral("name"), qs(stem)},
      {QStringLiteral("material"), qs("M_" + stem)},
  };
  if (exportsParallax(material)) {
    const Image height = engineHeightMap(*material.image(MapSlot::Height),
                                         material.parameterFlag(ParamId::HeightIsDepth));
    if (Status s = write("Height", height, SampleFormat::UInt16, false, "TC_GRAYSCALE"); !s)
      return makeError(s.error());
    root.insert(QStringLiteral("parallax"), unrealParallax(material, result.notes));
  }
  for (std::string& loss : engineLosses(material, Engine::Unreal))
    result.notes.push_back(std::move(loss));
  if (material.parameter(ParamId::NormalStrength) != 1.0 && material.hasMap(MapSlot::Normal)) {
    result.notes.push_back("normalStrength " +
                           engineNumber(material.parameter(ParamId::NormalStrength)) +
                           " is not applied in Unreal (the script wires the normal map as is)");
  }
  root.insert(QStringLiteral("textures"), textures);
  root.insert(QStringLiteral("constants"), constants);
  root.insert(QStringLiteral("parameters"),
              QJsonObject{{QStringLiteral("Tiling"), material.parameter(ParamId::Tiling)}});

  const std::string manifestFile = stem + "_unreal.json";
  result.mainPath = (directory / manifestFile).string();
  const QByteArray json = QJsonDocument(root).toJson(QJsonDocument::Indented);
  if (Status s = writeFileAtomically(result.mainPath, std::string_view(json.data(), json.size()));
      !s)
    return makeError(s.error());

  if (Status s = writeImportScript(directory, stem, manifestFile); !s)
    return makeError(s.error());
  return result;
}

}  // namespace relief::core::inline exporters
