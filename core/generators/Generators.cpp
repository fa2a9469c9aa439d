// Generators; see Generators.h.
#include "core/generators/Generators.h"

#include "core/generators/AmbientOcclusion.h"
#include "core/generators/Curvature.h"
#include "core/generators/HeightFromColor.h"
#include "core/generators/HeightFromNormal.h"
#include "core/generators/NormalFromHeight.h"

#include <cmath>
#include <cstdio>

namespace relief::core::inline generators {
namespace {

OptionSpec edgeOption(int defaultValue) {
  return choiceOption("edge", "Edges", {"wrap", "clamp"}, defaultValue,
                      "wrap: the map tiles, its left edge continues on the right (use for "
                      "tileable maps). clamp: the edges repeat their last texel.");
}

OptionSpec conventionOption(std::string_view description) {
  return choiceOption("convention", "Normal convention", {"opengl", "directx"}, 0, description);
}

std::vector<GeneratorInfo> buildTable() {
  return {
      {GeneratorKind::Normal,
       "normal",
       "Normal from height",
       "Tangent-space normals from the height map's slopes (reference 003, 1.4).",
       {{"in", "Height map", MapSlot::Height}},
       MapSlot::Normal,
       {choiceOption("kernel", "Kernel", {"central", "sobel", "scharr", "sobel5"}, 1,
                     "How slopes are measured: central differences (sharpest, noisiest), Sobel "
                     "3x3, Scharr 3x3 (more even in all directions), Sobel 5x5 (smoothest)."),
        numberOption("strength", "Strength", "slope per unit of height per texel", 0.01, 200.0, 4.0,
                     2,
                     "How steep the relief is: a height step of 1.0 over one texel becomes this "
                     "slope. heightScale x map width reproduces a material's depth exactly."),
        conventionOption("opengl: green is +Y up the image (Blender, Unity, Godot, glTF); "
                         "directx: green is +Y down (Unreal)."),
        edgeOption(0),
        numberOption("detailFine", "Fine detail", "weight", 0.0, 1.0, 1.0, 2,
                     "Weight of the slopes of the height as it is."),
        numberOption("detailMedium", "Medium detail", "weight", 0.0, 1.0, 0.0, 2,
                     "Weight of the slopes of the height blurred by 2 texels."),
        numberOption("detailLarge", "Large detail", "weight", 0.0, 1.0, 0.0, 2,
                     "Weight of the slopes of the height blurred by 4 texels."),
        numberOption("detailHuge", "Huge detail", "weight", 0.0, 1.0, 0.0, 2,
                     "Weight of the slopes of the height blurred by 8 texels.")}},
      {GeneratorKind::Height,
       "height",
       "Height from normal",
       "Integrates a normal map into a height map (Frankot-Chellappa, by FFT); the result is "
       "normalised to 0..1 and the relief's depth is reported.",
       {{"in", "Normal map", MapSlot::Normal}},
       MapSlot::Height,
       {conventionOption("The input's convention: opengl (+Y up) or directx (+Y down)."),
        edgeOption(1)}},
      {GeneratorKind::HeightFromColor,
       "height-from-color",
       "Height from colour",
       "A height guess from a photograph's brightness, with the large-scale shading removed.",
       {{"in", "Colour map", MapSlot::Color}},
       MapSlot::Height,
       {numberOption("radius", "High-pass radius", "texels", 0.0, 512.0, 64.0, 1,
                     "Brightness changes larger than this are treated as lighting, not height, "
                     "and removed. 0 keeps them."),
        numberOption("contrast", "Contrast", "factor around mid-grey", 0.0, 8.0, 1.0, 2,
                     "Steepens or flattens the height around its middle."),
        numberOption("levelsLow", "Levels: black", "input level", 0.0, 1.0, 0.0, 3,
                     "Input level that becomes the lowest height."),
        numberOption("levelsHigh", "Levels: white", "input level", 0.0, 1.0, 1.0, 3,
                     "Input level that becomes the highest height."),
        flagOption("invert", "Invert", false, "Dark is high (e.g. bright grout in a photo)."),
        edgeOption(0)}},
      {GeneratorKind::AmbientOcclusion,
       "ao",
       "Ambient occlusion from height",
       "Horizon-based occlusion: how much of the sky each texel sees over the relief around it.",
       {{"in", "Height map", MapSlot::Height}},
       MapSlot::AmbientOcclusion,
       {integerOption("directions", "Directions", "directions", 4, 64, 16,
                      "Directions searched for the horizon around each texel."),
        integerOption("steps", "Steps", "samples per direction", 2, 64, 16,
                      "Samples along each direction out to the radius."),
        numberOption("radius", "Radius", "texels", 1.0, 256.0, 32.0, 1,
                     "How far away relief can occlude."),
        numberOption("depth", "Depth", "texels per unit of height", 0.0, 512.0, 16.0, 1,
                     "How deep the relief is: a height difference of 1.0 counts as this many "
                     "texel widths (heightScale x map width for a material)."),
        numberOption("strength", "Strength", "factor", 0.0, 4.0, 1.0, 2,
                     "1 is the physical occlusion; more darkens further."),
        edgeOption(0)}},
      {GeneratorKind::Curvature,
       "curvature",
       "Curvature",
       "Convex (bright) and concave (dark) areas, for wear and dirt masks.",
       {{"in", "Height or normal map", MapSlot::Height}},
       MapSlot::AmbientOcclusion,
       {choiceOption("from", "Source", {"height", "normal"}, 0,
                     "Whether the input is a height map or a normal map."),
        numberOption("strength", "Strength", "gain around mid-grey", 0.0, 64.0, 4.0, 2,
                     "How strongly curvature departs from mid-grey."),
        numberOption("radius", "Blur radius", "texels", 0.0, 32.0, 1.0, 1,
                     "Smoothing before measuring: larger shows larger forms."),
        conventionOption("Convention of a normal-map input."), edgeOption(0)}},
      {GeneratorKind::Pack,
       "pack",
       "Pack height into normal alpha",
       "One RGBA texture with the normal in RGB and the height in A (references 001 and 003).",
       {{"normal", "Normal map", MapSlot::Normal}, {"height", "Height map", MapSlot::Height}},
       MapSlot::Normal,
       {flagOption("autoLevels", "Auto-levels height", true,
                   "Stretch the height to the full 0..1 range for precision; the material's "
                   "height scale and bias are adjusted so the relief stays the same."),
        flagOption("invertHeight", "Invert height", false, "Store depth instead of height.")}},
  };
}

template <class Enum>
Enum choiceValue(const GeneratorValues& values, GeneratorKind kind, std::string_view name) {
  return Enum(int(values[std::size_t(findGeneratorOption(kind, name))]));
}

double numberValue(const GeneratorValues& values, GeneratorKind kind, std::string_view name) {
  return values[std::size_t(findGeneratorOption(kind, name))];
}

std::string formatted(const char* format, double value) {
  char buffer[128];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

}  // namespace

std::span<const GeneratorInfo> allGenerators() {
  static const std::vector<GeneratorInfo> table = buildTable();
  return table;
}

const GeneratorInfo& generatorInfo(GeneratorKind kind) {
  return allGenerators()[std::size_t(kind)];
}

std::optional<GeneratorKind> findGenerator(std::string_view name) {
  for (const GeneratorInfo& info : allGenerators()) {
    if (info.name == name)
      return info.kind;
  }
  return std::nullopt;
}

GeneratorValues defaultGeneratorValues(GeneratorKind kind) {
  GeneratorValues values;
  for (const OptionSpec& option : generatorInfo(kind).options)
    values.push_back(option.defaultValue);
  return values;
}

int findGeneratorOption(GeneratorKind kind, std::string_view name) {
  const std::vector<OptionSpec>& options = generatorInfo(kind).options;
  for (std::size_t i = 0; i < options.size(); ++i) {
    if (options[i].name == name)
      return int(i);
  }
  return -1;
}

Result<GeneratedMap> runGenerator(const GeneratorRequest& request, const WorkControl& control) {
  const GeneratorInfo& info = generatorInfo(request.kind);
  if (request.inputs.size() != info.inputs.size()) {
    return makeError(std::string(info.name) + " needs " + std::to_string(info.inputs.size()) +
                     " input(s)");
  }
  for (std::size_t i = 0; i < request.inputs.size(); ++i) {
    if (!request.inputs[i] || request.inputs[i]->isEmpty()) {
      return makeError(std::string(info.name) + ": no " + std::string(info.inputs[i].label) +
                       " to generate from");
    }
  }
  GeneratorValues values =
      request.values.empty() ? defaultGeneratorValues(request.kind) : request.values;
  if (values.size() != info.options.size())
    return makeError("wrong number of option values");
  for (std::size_t i = 0; i < values.size(); ++i) {
    values[i] = sanitizeOptionValue(info.options[i], values[i]);
  }
  const GeneratorKind kind = request.kind;
  const Image& input = *request.inputs.front();
  const int edgeOption = findGeneratorOption(kind, "edge");
  const EdgeMode edge =
      edgeOption >= 0 ? EdgeMode(int(values[std::size_t(edgeOption)])) : EdgeMode::Wrap;
  GeneratedMap result;

  switch (kind) {
    case GeneratorKind::Normal: {
      NormalFromHeightOptions options;
      options.kernel = choiceValue<GradientKernel>(values, kind, "kernel");
      // Slopes per texel are 1/texelScale steeper on a reduced preview.
      options.strength = float(numberValue(values, kind, "strength") * request.texelScale);
      options.convention = choiceValue<NormalConvention>(values, kind, "convention");
      options.edge = edge;
      options.detailWeights = {float(numberValue(values, kind, "detailFine")),
                               float(numberValue(values, kind, "detailMedium")),
                               float(numberValue(values, kind, "detailLarge")),
                               float(numberValue(values, kind, "detailHuge"))};
      options.texelScale = request.texelScale;
      result.image = normalMapFromHeight(input, options, control);
      break;
    }
    case GeneratorKind::Height: {
      HeightFromNormalOptions options;
      options.convention = choiceValue<NormalConvention>(values, kind, "convention");
      options.edge = edge;
      Result<HeightFromNormalResult> height = heightFromNormal(input, options, control);
      if (!height)
        return makeError(height.error());
      const double depth = height->rangeTexels / request.texelScale;
      result.image = std::move(height->height);
      result.depthTexels = depth;
      result.notes.push_back(formatted("relief depth %.1f texels", depth) +
                             formatted(" (heightScale %.4f UV units reproduces it)",
                                       depth / (double(input.width()) / request.texelScale)));
      break;
    }
    case GeneratorKind::HeightFromColor: {
      HeightFromColorOptions options;
      options.highPassRadius = numberValue(values, kind, "radius");
      options.contrast = numberValue(values, kind, "contrast");
      options.levelsLow = numberValue(values, kind, "levelsLow");
      options.levelsHigh = numberValue(values, kind, "levelsHigh");
      options.invert = numberValue(values, kind, "invert") != 0.0;
      options.edge = edge;
      options.texelScale = request.texelScale;
      result.image = heightFromColor(input, options, control);
      break;
    }
    case GeneratorKind::AmbientOcclusion: {
      AmbientOcclusionOptions options;
      options.directions = int(numberValue(values, kind, "directions"));
      options.steps = int(numberValue(values, kind, "steps"));
      options.radius = numberValue(values, kind, "radius");
      options.depth = numberValue(values, kind, "depth");
      options.strength = numberValue(values, kind, "strength");
      options.edge = edge;
      options.texelScale = request.texelScale;
      result.image = ambientOcclusionFromHeight(input, options, control);
      break;
    }
    case GeneratorKind::Curvature: {
      CurvatureOptions options;
      options.source = choiceValue<CurvatureSource>(values, kind, "from");
      options.strength = numberValue(values, kind, "strength");
      options.blurRadius = numberValue(values, kind, "radius");
      options.convention = choiceValue<NormalConvention>(values, kind, "convention");
      options.edge = edge;
      options.texelScale = request.texelScale;
      result.image = curvatureMap(input, options, control);
      break;
    }
    case GeneratorKind::Pack: {
      const Image& heightMap = *request.inputs[1];
      if (heightMap.width() != input.width() || heightMap.height() != input.height()) {
        return makeError("pack: the normal map (" + std::to_string(input.width()) + "x" +
                         std::to_string(input.height()) + ") and the height map (" +
                         std::to_string(heightMap.width()) + "x" +
                         std::to_string(heightMap.height()) + ") differ in size");
      }
      Image height = heightMap;
      if (numberValue(values, kind, "invertHeight") != 0.0) {
        for (std::size_t i = 0; i < height.pixelCount(); ++i) {
          float& v = height.data()[i * std::size_t(height.channels())];
          v = 1.0f - v;
        }
      }
      if (numberValue(values, kind, "autoLevels") != 0.0) {
        const LevelsRange range = autoLevels(height);
        result.levels = range;
        result.notes.push_back(formatted("height stretched from %.4f", range.low) +
                               formatted(" .. %.4f to 0..1", range.high));
      }
      result.image = packHeightIntoNormalAlpha(input, height);
      break;
    }
  }
  if (control.cancelled())
    return makeError("cancelled");
  return result;
}

std::optional<std::string> normalMapWarning(const Image& image) {
  if (image.channels() < 3) {
    return "the normal map has " + std::to_string(image.channels()) +
           " channel(s); a tangent-space normal map needs X, Y and Z";
  }
  // Sample up to ~64k texels: enough to judge, quick at 8K.
  const std::size_t count = image.pixelCount();
  const std::size_t stride = std::max<std::size_t>(1, count / 65536);
  std::size_t checked = 0, odd = 0;
  for (std::size_t i = 0; i < count; i += stride) {
    const float* p = image.data() + i * std::size_t(image.channels());
    const float x = 2.0f * p[0] - 1.0f, y = 2.0f * p[1] - 1.0f, z = 2.0f * p[2] - 1.0f;
    const float length = std::sqrt(x * x + y * y + z * z);
    odd += (length < 0.8f || length > 1.2f || z < 0.0f);
    ++checked;
  }
  const double share = double(odd) / double(std::max<std::size_t>(checked, 1));
  if (share <= 0.2)
    return std::nullopt;
  return formatted(
      "%.0f%% of its texels are not unit vectors pointing out of the surface; it "
      "does not look like a tangent-space normal map (a photograph?), so the "
      "result will not mean much",
      100.0 * share);
}

}  // namespace relief::core::inline generators
