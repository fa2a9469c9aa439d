// The parameter table; see Parameters.h. Every number an artist can tune is declared here
// once, with the reference it comes from where there is one.
#include "core/material/Parameters.h"

#include <algorithm>
#include <iterator>

namespace relief::core::inline material {
namespace {

constexpr std::string_view kRelief = "Relief";
constexpr std::string_view kSampling = "Sampling";
constexpr std::string_view kShadows = "Self-shadowing";
constexpr std::string_view kMapping = "Mapping";
constexpr std::string_view kSurface = "Surface";

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// When it has an effect and which uniform carries it ("" for a shader-variant switch).
struct Binding {
  ParamUse use = ParamUse::Always;
  std::string_view uniform;
  double uniformScale = 1.0;
};

ParameterSpec parameter(ParamId id, std::string_view group, Binding binding, OptionSpec option) {
  ParameterSpec spec;
  static_cast<OptionSpec&>(spec) = std::move(option);
  spec.id = id;
  spec.group = group;
  spec.use = binding.use;
  spec.uniform = binding.uniform;
  spec.uniformScale = binding.uniformScale;
  return spec;
}

// The relief: its depth, where it sits, how the height map is read.
std::vector<ParameterSpec> reliefParameters() {
  // clang-format off
  return {
    parameter(ParamId::HeightScale, kRelief, {ParamUse::Always, "uHeightScale"}, numberOption(
        "heightScale", "Height scale", "UV units (fractions of the texture width)",
        0.0, 0.25, 0.04, 3,
        "Depth of the relief: heights 0..1 span this many texture widths. The surface height "
        "is h * heightScale + heightBias (references 000 and 004). On a mesh whose texels vary "
        "in size or shape (a sphere), widths at the mesh's mean texel size, as the "
        "displacement technique measures them: one depth in world units everywhere.")),
    parameter(ParamId::HeightBias, kRelief, {ParamUse::Always, "uHeightBias"}, numberOption(
        "heightBias", "Height bias", "UV units", -0.25, 0.25, -0.04, 3,
        "Moves the relief relative to the mesh surface (the reference plane of the marching "
        "techniques). -heightScale puts the top (h = 1) on the surface, as in POM; "
        "-heightScale/2 centres it, as in reference 004 (h * 0.04 - 0.02).")),
    parameter(ParamId::HeightIsDepth, kRelief, {ParamUse::Always, "uHeightIsDepth"}, flagOption(
        "heightIsDepth", "Height map is a depth map", false,
        "Read the height map as depth (white = deepest), as some tools export it.")),
    parameter(ParamId::HeightInNormalAlpha, kRelief, {ParamUse::Always, ""}, flagOption(
        "heightInNormalAlpha", "Height in normal map alpha", false,
        "Take the height from the normal map's alpha channel instead of the height map (the "
        "packed layout of references 001 and 003).")),
  };
  // clang-format on
}

// How densely the techniques sample the height field.
std::vector<ParameterSpec> samplingParameters() {
  // clang-format off
  return {
    parameter(ParamId::MinSamples, kSampling, {ParamUse::Marching, "uMinSamples"}, integerOption(
        "minSamples", "Min samples", "samples", 1, 256, 8,
        "The fewest height samples along the view ray (looking straight at the surface, the "
        "count of reference 001).")),
    parameter(ParamId::MaxSamples, kSampling, {ParamUse::Marching, "uMaxSamples"}, integerOption(
        "maxSamples", "Max samples", "samples", 1, 256, 128,
        "The most height samples along the view ray, reached at grazing angles (reference "
        "001). More samples catch thinner features and cost more.")),
    parameter(ParamId::SamplesPerTexel, kSampling, {ParamUse::Marching, "uSamplesPerTexel"}, numberOption(
        "samplesPerTexel", "Samples per texel", "samples per texel the view ray crosses",
        0.0, 4.0, 2.0, 2,
        "The view ray takes this many samples per texel it crosses on its way through the "
        "relief (at the mip level read there), between min and max samples, so grazing views "
        "show no slices and straight-on views cost little. Reference 001 names one per texel "
        "as the ideal; the filtered field between two samples a texel apart still bends, and "
        "two per texel are needed for a grazing view to match 256 samples within 43 dB "
        "(docs/techniques.md). 0 lerps between min and max by the view angle alone "
        "(reference 001's rule).")),
    parameter(ParamId::RefinementSteps, kSampling, {ParamUse::Refinement, "uRefinementSteps"}, integerOption(
        "refinementSteps", "Refinement steps", "binary search steps", 0, 16, 5,
        "Relief mapping only: binary search steps after the linear search; each halves the "
        "remaining error.")),
    parameter(ParamId::LodFade, kSampling, {ParamUse::PerPixel, "uLodFade"}, numberOption(
        "lodFade", "Fade at mip level", "mip levels", 0.0, 12.0, 0.0, 1,
        "Fades the relief out to plain normal mapping where the height map is sampled at this "
        "mip level (far away or at grazing angles), over the level before it. Saves the "
        "marching cost where it cannot be seen. 0 never fades.")),
    parameter(ParamId::MaxTessellation, kSampling, {ParamUse::Tessellation, "uMaxTessellation"}, integerOption(
        "maxTessellation", "Max tessellation", "segments per triangle edge", 1, 64, 32,
        "Displacement only: the most segments each triangle edge is split into. Edges are "
        "split into segments about 4 pixels long on screen and no shorter than a quarter "
        "texel of the height map, up to this many.")),
  };
  // clang-format on
}

// Self-shadowing.
std::vector<ParameterSpec> shadowParameters() {
  // clang-format off
  return {
    parameter(ParamId::ShadowMode, kShadows, {ParamUse::Always, ""}, choiceOption(
        "shadowMode", "Shadows", {"off", "hard", "soft"}, 2,
        "Self-shadowing by marching from the visible point toward the light (reference 003, "
        "1.3): hard is lit or shadowed, soft estimates a penumbra (Tatarchuk).")),
    parameter(ParamId::ShadowStrength, kShadows, {ParamUse::Shadows, "uShadowStrength"}, numberOption(
        "shadowStrength", "Shadow strength", "fraction of direct light removed",
        0.0, 1.0, 0.8, 2,
        "How dark self-shadows are: 0 has no effect, 1 removes all direct light.")),
    parameter(ParamId::ShadowSamples, kShadows, {ParamUse::Shadows, "uShadowSamples"}, integerOption(
        "shadowSamples", "Shadow samples", "samples", 1, 128, 16,
        "Height samples along the ray toward the light.")),
    parameter(ParamId::ShadowSoftness, kShadows, {ParamUse::SoftShadows, "uShadowSoftness", kRadiansPerDegree}, numberOption(
        "shadowSoftness", "Light size", "degrees (angular diameter of the light)",
        0.0, 45.0, 8.0, 1,
        "Soft shadows: the apparent size of the light. Larger lights give wider penumbras; 0 "
        "gives hard edges.")),
    parameter(ParamId::ShadowLimit, kShadows, {ParamUse::Shadows, "uShadowLimit"}, flagOption(
        "shadowLimit", "Limit shadow length", false,
        "Welsh's offset limit applied to the light ray (reference 003, 1.3): the light ray "
        "climbs as if the light were at least 45 degrees high, so shadows of a low light stay "
        "short instead of stretching across the surface. Off is physically exact.")),
  };
  // clang-format on
}

// How texture coordinates map the material onto the mesh.
std::vector<ParameterSpec> mappingParameters() {
  // clang-format off
  return {
    parameter(ParamId::Tiling, kMapping, {ParamUse::Always, "uTiling"}, numberOption(
        "tiling", "Tiling", "repeats across the mesh UV range", 0.1, 16.0, 1.0, 2,
        "How many times the maps repeat across the mesh's UV range.")),
    parameter(ParamId::UvEdge, kMapping, {ParamUse::Always, ""}, choiceOption(
        "uvEdge", "UV edge", {"repeat", "clamp"}, 0,
        "repeat: the relief continues across the mesh's UV border. clamp: texels displaced "
        "outside the UV range are discarded, so a plane shows the relief's silhouette at its "
        "edges.")),
    parameter(ParamId::DepthOffset, kMapping, {ParamUse::PerPixel, ""}, flagOption(
        "depthOffset", "Write displaced depth", false,
        "Write the depth of the displaced surface (gl_FragDepth), so it meets other geometry "
        "where the relief really is. Disables early depth testing.")),
    parameter(ParamId::CurvedSilhouettes, kMapping, {ParamUse::Marching, ""}, flagOption(
        "curvedSilhouettes", "Silhouettes on curved meshes", false,
        "The marches follow the mesh's curvature (curved relief mapping, Oliveira and "
        "Policarpo 2005, with the curvature taken per pixel): a ray that passes under the "
        "relief's top without meeting it leaves the surface, so the relief shapes the mesh's "
        "outline instead of ending at it. No change on flat meshes.")),
  };
  // clang-format on
}

// The surface's shading: normals, the shading model and its constants.
std::vector<ParameterSpec> surfaceParameters() {
  // clang-format off
  return {
    parameter(ParamId::NormalStrength, kSurface, {ParamUse::Always, "uNormalStrength"}, numberOption(
        "normalStrength", "Normal strength", "factor on normal X/Y", 0.0, 4.0, 1.0, 2,
        "Scales the tilt of the normal map (its X and Y) before renormalising; 0 shows the "
        "surface flat, 1 as authored.")),
    parameter(ParamId::NormalYDown, kSurface, {ParamUse::Always, "uNormalYDown"}, flagOption(
        "normalYDown", "DirectX normal map (Y down)", false,
        "Read the normal map's green channel as Y pointing down (DirectX/Unreal convention) "
        "instead of up (OpenGL/Blender/Godot/glTF).")),
    parameter(ParamId::Shading, kSurface, {ParamUse::Always, ""}, choiceOption(
        "shading", "Shading", {"classic", "pbr"}, 1,
        "pbr: the glTF 2.0 metallic-roughness BRDF (GGX, Smith height-correlated visibility, "
        "Schlick Fresnel, Lambert diffuse) under the light and the environment's image-based "
        "light, as engines shade. classic: Blinn-Phong under the light with a flat ambient "
        "term (the reference documents' look).")),
    parameter(ParamId::Metallic, kSurface, {ParamUse::Pbr, "uMetallic"}, numberOption(
        "metallic", "Metallic", "0 dielectric .. 1 metal", 0.0, 1.0, 0.0, 2,
        "glTF metallicFactor: 0 is a dielectric (plastic, stone, wood) whose colour is its "
        "diffuse albedo, 1 a metal whose colour tints its reflection.")),
    parameter(ParamId::Roughness, kSurface, {ParamUse::Pbr, "uRoughness"}, numberOption(
        "roughness", "Roughness", "perceptual roughness, 0 mirror .. 1 matte", 0.0, 1.0, 0.5, 2,
        "glTF roughnessFactor: multiplies the roughness map where there is one. The GGX width "
        "is its square.")),
    parameter(ParamId::Specular, kSurface, {ParamUse::Classic, "uSpecular"}, numberOption(
        "specular", "Specular", "fraction of the light colour", 0.0, 1.0, 0.25, 2,
        "Strength of the Blinn-Phong highlight.")),
    parameter(ParamId::Shininess, kSurface, {ParamUse::Classic, "uShininess"}, numberOption(
        "shininess", "Shininess", "Blinn-Phong exponent", 1.0, 256.0, 32.0, 0,
        "Sharpness of the highlight: the exponent on N.H. A roughness map, when present, "
        "scales it down per texel.")),
  };
  // clang-format on
}

// The rows in ParamId order (parameterSpec indexes them by id), one function per panel section.
std::vector<ParameterSpec> buildTable() {
  std::vector<ParameterSpec> table;
  for (const auto& section : {reliefParameters, samplingParameters, shadowParameters,
                              mappingParameters, surfaceParameters}) {
    std::vector<ParameterSpec> rows = section();
    std::move(rows.begin(), rows.end(), std::back_inserter(table));
  }
  return table;
}

}  // namespace

std::span<const ParameterSpec> allParameters() {
  static const std::vector<ParameterSpec> table = buildTable();
  return table;
}

const ParameterSpec& parameterSpec(ParamId id) {
  return allParameters()[std::size_t(id)];
}

std::optional<ParamId> findParameter(std::string_view name) {
  for (const ParameterSpec& spec : allParameters()) {
    if (spec.name == name) {
      return spec.id;
    }
  }
  return std::nullopt;
}

bool parameterInUse(const ParameterSpec& spec, Technique technique, ShadowMode shadows,
                    ShadingModel shading) {
  switch (spec.use) {
    case ParamUse::Always:
      return true;
    case ParamUse::Marching:  // the layered marches' sample counts; exact tracing needs none
      return isMarchingTechnique(technique) && !isExactTracing(technique);
    case ParamUse::Refinement:
      return technique == Technique::Relief;
    case ParamUse::Shadows:
      return shadows != ShadowMode::Off;
    case ParamUse::SoftShadows:
      return shadows == ShadowMode::Soft;
    case ParamUse::Tessellation:
      return technique == Technique::Displacement;
    case ParamUse::PerPixel:
      return technique != Technique::Displacement;
    case ParamUse::Classic:
      return shading == ShadingModel::Classic;
    case ParamUse::Pbr:
      return shading == ShadingModel::Pbr;
  }
  return true;
}

ParameterValues defaultParameterValues() {
  ParameterValues values{};
  for (const ParameterSpec& spec : allParameters()) {
    values[std::size_t(spec.id)] = spec.defaultValue;
  }
  return values;
}

}  // namespace relief::core::inline material
