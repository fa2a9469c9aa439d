// Generators; see Generators.h.
#include "core/generators/Generators.h"

#include "core/generators/AmbientOcclusion.h"
#include "core/generators/Curvature.h"
#include "core/generators/Delight.h"
#include "core/generators/HeightFromColor.h"
#include "core/generators/HeightFromNormal.h"
#include "core/generators/NormalFromHeight.h"
#include "core/generators/SurfaceGuess.h"

#include <array>
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

// pack's layouts in the order of its "layout" choice (names from ChannelPacking's table);
// the first, height in normal alpha, is the default.
constexpr std::array<std::string_view, 4> kPackLayoutChoices = {"normal-height", "orm",
                                                                "unity-mask", "unity-metallic"};

GeneratorInfo normalGenerator() {
  return GeneratorInfo{
      GeneratorKind::Normal,
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
                    "Weight of the slopes of the height blurred by 8 texels.")}};
}

GeneratorInfo heightGenerator() {
  return GeneratorInfo{
      GeneratorKind::Height,
      "height",
      "Height from normal",
      "Integrates a normal map into a height map (Frankot-Chellappa, by FFT); the result is "
      "normalised to 0..1 and the relief's depth is reported.",
      {{"in", "Normal map", MapSlot::Normal}},
      MapSlot::Height,
      {conventionOption("The input's convention: opengl (+Y up) or directx (+Y down)."),
       edgeOption(1)}};
}

GeneratorInfo heightFromColorGenerator() {
  return GeneratorInfo{
      GeneratorKind::HeightFromColor,
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
       edgeOption(0)}};
}

GeneratorInfo ambientOcclusionGenerator() {
  return GeneratorInfo{
      GeneratorKind::AmbientOcclusion,
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
       edgeOption(0)}};
}

GeneratorInfo curvatureGenerator() {
  return GeneratorInfo{GeneratorKind::Curvature,
                       "curvature",
                       "Curvature",
                       "Convex (bright) and concave (dark) areas, for wear and dirt masks.",
                       {{"in", "Height or normal map", MapSlot::Height}},
                       MapSlot::AmbientOcclusion,
                       {choiceOption("from", "Source", {"height", "normal"}, 0,
                                     "Whether the input is a height map or a normal map."),
                        numberOption("strength", "Strength", "gain around mid-grey", 0.0, 64.0, 4.0,
                                     2, "How strongly curvature departs from mid-grey."),
                        numberOption("radius", "Blur radius", "texels", 0.0, 32.0, 1.0, 1,
                                     "Smoothing before measuring: larger shows larger forms."),
                        conventionOption("Convention of a normal-map input."), edgeOption(0)}};
}

GeneratorInfo packGenerator() {
  return GeneratorInfo{
      GeneratorKind::Pack,
      "pack",
      "Pack channels",
      "One texture from several maps, in a layout renderers read: the normal with the height "
      "in alpha (references 001 and 003: one fetch), or ORM and Unity mask maps for engines. "
      "Maps not given take their neutral value (AO 1, roughness 1, metallic 0).",
      {{"normal", "Normal map", MapSlot::Normal, true},
       {"height", "Height map", MapSlot::Height, true},
       {"ao", "Ambient occlusion map", MapSlot::AmbientOcclusion, true},
       {"roughness", "Roughness map", MapSlot::Roughness, true},
       {"metallic", "Metallic map", MapSlot::Metallic, true}},
      MapSlot::Normal,
      {choiceOption("layout", "Layout", {kPackLayoutChoices.begin(), kPackLayoutChoices.end()}, 0,
                    "normal-height: the normal's RGB and the height in A. orm: R occlusion, G "
                    "roughness, B metallic (glTF, Unreal). unity-mask: R metallic, G occlusion, "
                    "B detail mask, A smoothness (HDRP). unity-metallic: R metallic, A "
                    "smoothness (URP, Built-in)."),
       flagOption("autoLevels", "Auto-levels height", true,
                  "normal-height: stretch the height to the full 0..1 range for precision; the "
                  "material's height scale and bias are adjusted so the relief stays the same."),
       flagOption("invertHeight", "Invert height", false,
                  "normal-height: store depth instead of height.")}};
}

GeneratorInfo delightGenerator() {
  return GeneratorInfo{
      GeneratorKind::Delight,
      "delight",
      "Remove baked light",
      "Flattens the light a photograph was taken in (broad gradients, soft shadows) into an "
      "albedo: the linear luminance blurred over the radius is taken for the light and divided "
      "out, relative to its mean. Detail smaller than the radius stays.",
      {{"in", "Colour map (a photograph)", MapSlot::Color}},
      MapSlot::Color,
      {numberOption("radius", "Radius", "texels", 2.0, 1024.0, 64.0, 1,
                    "Light that changes over more than this many texels is removed; keep it "
                    "larger than the surface's own features (stones, planks)."),
       numberOption("strength", "Strength", "fraction", 0.0, 1.0, 1.0, 2,
                    "1 divides the estimated light out entirely; less keeps some of it."),
       edgeOption(0)}};
}

GeneratorInfo roughnessGenerator() {
  return GeneratorInfo{
      GeneratorKind::Roughness,
      "roughness",
      "Roughness from colour",
      "Guesses roughness from a photograph: its luminance, between the image's own 5th and 95th "
      "percentiles, runs from the roughest (dark pores, dust) to the smoothest (exposed, worn "
      "tops); saturated colour and, with a height map, cavities and ridges adjust it.",
      {{"in", "Colour map (a photograph)", MapSlot::Color},
       {"height", "Height map (for cavities)", MapSlot::Height, true}},
      MapSlot::Roughness,
      {numberOption("roughest", "Roughest", "roughness", 0.0, 1.0, 0.9, 2,
                    "The roughness of the darkest texels (the 5th percentile of luminance)."),
       numberOption("smoothest", "Smoothest", "roughness", 0.0, 1.0, 0.45, 2,
                    "The roughness of the brightest texels (the 95th percentile)."),
       numberOption("saturation", "Saturated colour", "", -1.0, 1.0, 0.0, 2,
                    "How much smoother (positive) or rougher (negative) a fully saturated "
                    "texel is: paint and glaze are smoother than the grey around them."),
       numberOption("cavity", "Cavity", "", 0.0, 1.0, 0.3, 2,
                    "With a height map: how much rougher the deepest cavities get (and "
                    "smoother the ridges), up to half the range."),
       numberOption("radius", "Cavity radius", "texels", 0.0, 64.0, 2.0, 1,
                    "The height is blurred over this before its cavities are found."),
       edgeOption(0)}};
}

GeneratorInfo metallicGenerator() {
  return GeneratorInfo{
      GeneratorKind::Metallic,
      "metallic",
      "Metallic from colour",
      "Guesses where a photograph shows bare metal: texels whose linear luminance and "
      "saturation both fall in the ranges (bright; grey for steel and aluminium, saturated "
      "for gold and copper). Check the share it reports: bright plaster reads as metal too.",
      {{"in", "Colour map (a photograph)", MapSlot::Color}},
      MapSlot::Metallic,
      {numberOption("brightnessLow", "Brightness from", "linear", 0.0, 1.0, 0.5, 2,
                    "Metal is at least this bright (bare metals' albedo is above about 0.5)."),
       numberOption("brightnessHigh", "Brightness to", "linear", 0.0, 1.0, 1.0, 2,
                    "... and at most this bright."),
       numberOption("saturationLow", "Saturation from", "", 0.0, 1.0, 0.0, 2,
                    "Metal is at least this saturated (raise it for gold or copper only)."),
       numberOption("saturationHigh", "Saturation to", "", 0.0, 1.0, 0.25, 2,
                    "... and at most this saturated (0.25: grey metals; 0.7 takes gold and "
                    "copper in)."),
       numberOption("softness", "Softness", "", 0.0, 0.5, 0.05, 2,
                    "The width of the ranges' soft edges.")}};
}

// One function per generator, in GeneratorKind order (generatorInfo indexes them by kind).
std::vector<GeneratorInfo> buildTable() {
  return {normalGenerator(),           heightGenerator(),    heightFromColorGenerator(),
          ambientOcclusionGenerator(), curvatureGenerator(), packGenerator(),
          delightGenerator(),          roughnessGenerator(), metallicGenerator()};
}

template <class Enum>
Enum choiceValue(const GeneratorValues& values, GeneratorKind kind, std::string_view name) {
  return Enum(int(values[std::size_t(findGeneratorOption(kind, name))]));
}

double numberValue(const GeneratorValues& values, GeneratorKind kind, std::string_view name) {
  return values[std::size_t(findGeneratorOption(kind, name))];
}

std::string formatted(const char* format, double value) {
  char buffer[512];  // the longest message, normalMapWarning's, is about 200 bytes
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

// pack: height into normal alpha (auto-levelled, the range reported so the material can keep
// its relief), or one of ChannelPacking's layouts from whichever maps are given.
Result<GeneratedMap> runPack(const GeneratorRequest& request, const GeneratorValues& values) {
  const GeneratorKind kind = GeneratorKind::Pack;
  const std::string_view layoutName =
      kPackLayoutChoices[std::size_t(numberValue(values, kind, "layout"))];
  const GeneratorInfo& info = generatorInfo(kind);
  GeneratedMap result;
  if (layoutName != "normal-height") {
    std::vector<NamedMap> maps;
    for (std::size_t i = 0; i < request.inputs.size(); ++i) {
      if (request.inputs[i])
        maps.push_back({std::string(info.inputs[i].name), request.inputs[i]});
    }
    std::vector<std::string> substituted;
    const std::vector<std::string> terms =
        resolveLayoutTerms(*findPackLayout(layoutName), maps, &substituted);
    Result<Image> packed = packChannels(maps, terms);
    if (!packed)
      return makeError(packed.error());
    result.image = std::move(packed).value();
    for (const std::string& name : substituted)
      result.notes.push_back(neutralValueNote(name));
    return result;
  }
  if (!request.inputs[0] || !request.inputs[1])
    return makeError("height in normal alpha needs the normal map and the height map");
  const Image& normals = *request.inputs[0];
  const Image& heightMap = *request.inputs[1];
  if (heightMap.width() != normals.width() || heightMap.height() != normals.height()) {
    return makeError("the normal map (" + std::to_string(normals.width()) + "x" +
                     std::to_string(normals.height()) + ") and the height map (" +
                     std::to_string(heightMap.width()) + "x" + std::to_string(heightMap.height()) +
                     ") differ in size");
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
  result.image = packHeightIntoNormalAlpha(normals, height);
  return result;
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

namespace {

// The request with trailing optional inputs filled in as null, its inputs checked, and its
// option values (the defaults when none are given) kept within their declared ranges.
Result<GeneratorRequest> completedRequest(const GeneratorRequest& given) {
  const GeneratorInfo& info = generatorInfo(given.kind);
  // Trailing optional inputs may be left out of the list.
  GeneratorRequest request = given;
  while (request.inputs.size() < info.inputs.size() && info.inputs[request.inputs.size()].optional)
    request.inputs.push_back(nullptr);
  if (request.inputs.size() != info.inputs.size()) {
    return makeError(std::string(info.name) + " needs " + std::to_string(info.inputs.size()) +
                     " input(s)");
  }
  for (std::size_t i = 0; i < request.inputs.size(); ++i) {
    if (info.inputs[i].optional && !request.inputs[i])
      continue;
    if (!request.inputs[i] || request.inputs[i]->isEmpty()) {
      return makeError(std::string(info.name) + ": no " + std::string(info.inputs[i].label) +
                       " to generate from");
    }
  }
  if (request.values.empty())
    request.values = defaultGeneratorValues(request.kind);
  if (request.values.size() != info.options.size())
    return makeError("wrong number of option values");
  for (std::size_t i = 0; i < request.values.size(); ++i)
    request.values[i] = sanitizeOptionValue(info.options[i], request.values[i]);
  return request;
}

}  // namespace

Result<GeneratedMap> runGenerator(const GeneratorRequest& given, const WorkControl& control) {
  Result<GeneratorRequest> completed = completedRequest(given);
  if (!completed)
    return makeError(completed.error());
  const GeneratorRequest& request = completed.value();
  const GeneratorValues& values = request.values;
  const GeneratorKind kind = request.kind;
  if (kind == GeneratorKind::Pack)
    return runPack(request, values);
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
    case GeneratorKind::Pack:
      break;  // runPack, above
    case GeneratorKind::Delight: {
      DelightOptions options;
      options.radius = numberValue(values, kind, "radius");
      options.strength = numberValue(values, kind, "strength");
      options.edge = edge;
      options.texelScale = request.texelScale;
      DelightResult delit = delight(input, options, control);
      result.image = std::move(delit.albedo);
      result.notes.push_back(formatted("the baked light ranged from %.2fx", delit.lightLow) +
                             formatted(" to %.2fx of its mean", delit.lightHigh) +
                             formatted(" (RMS %.0f%%)", 100.0 * delit.lightRms) +
                             formatted("; divided out at strength %.2f", options.strength));
      break;
    }
    case GeneratorKind::Roughness: {
      const Image* height = request.inputs.size() > 1 ? request.inputs[1] : nullptr;
      if (height && (height->width() != input.width() || height->height() != input.height())) {
        return makeError("the height map is " + std::to_string(height->width()) + "x" +
                         std::to_string(height->height()) + ", the colour map " +
                         std::to_string(input.width()) + "x" + std::to_string(input.height()) +
                         "; give maps of one size");
      }
      RoughnessGuessOptions options;
      options.roughest = numberValue(values, kind, "roughest");
      options.smoothest = numberValue(values, kind, "smoothest");
      options.saturation = numberValue(values, kind, "saturation");
      options.cavity = numberValue(values, kind, "cavity");
      options.cavityRadius = numberValue(values, kind, "radius");
      options.edge = edge;
      options.texelScale = request.texelScale;
      SurfaceGuess guess = guessRoughness(input, height, options, control);
      result.image = std::move(guess.map);
      result.notes.push_back(
          formatted("roughness %.2f", guess.low) + formatted(" to %.2f", guess.high) +
          formatted(", mean %.2f", guess.mean) +
          (height ? std::string() : std::string("; no height map: no cavities")));
      break;
    }
    case GeneratorKind::Metallic: {
      MetallicGuessOptions options;
      options.brightnessLow = numberValue(values, kind, "brightnessLow");
      options.brightnessHigh = numberValue(values, kind, "brightnessHigh");
      options.saturationLow = numberValue(values, kind, "saturationLow");
      options.saturationHigh = numberValue(values, kind, "saturationHigh");
      options.softness = numberValue(values, kind, "softness");
      SurfaceGuess guess = guessMetallic(input, options, control);
      result.image = std::move(guess.map);
      result.notes.push_back(
          formatted("%.1f%% of the texels read as metal", 100.0 * guess.metalFraction));
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
