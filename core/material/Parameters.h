// The material parameters, declared once: name (the preset key and the CLI's --set name),
// label, unit, range and default. The UI builds its controls from this table, presets store
// values under these names and the CLI parses them, so nothing is declared twice.
#pragma once

#include "core/base/OptionSpec.h"
#include "core/base/Result.h"
#include "core/material/Technique.h"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace relief::core::inline material {

enum class ParamId {
  // Relief
  HeightScale,
  HeightBias,
  HeightIsDepth,
  HeightInNormalAlpha,
  // Sampling
  MinSamples,
  MaxSamples,
  SamplesPerTexel,
  RefinementSteps,
  LodFade,
  MaxTessellation,
  // Self-shadowing
  ShadowMode,
  ShadowStrength,
  ShadowSamples,
  ShadowSoftness,
  ShadowLimit,
  // Mapping
  Tiling,
  UvEdge,
  DepthOffset,
  CurvedSilhouettes,
  // Surface
  NormalStrength,
  NormalYDown,
  Shading,
  Metallic,
  Roughness,
  Specular,
  Shininess,
  Count,
};

// Values of the Choice parameters.
enum class ShadowMode { Off, Hard, Soft };
enum class UvEdge { Repeat, Clamp };
enum class ShadingModel { Classic, Pbr };

constexpr std::size_t kParamCount = std::size_t(ParamId::Count);

// When a parameter has an effect; the Parameters panel greys out the others.
enum class ParamUse {
  Always,
  Marching,      // the layered marches (steep, POM, relief): their sample counts
  Refinement,    // relief mapping's binary refinement
  Shadows,       // self-shadowing on, hard or soft
  SoftShadows,   // soft self-shadowing
  Tessellation,  // the displacement technique's tessellation
  PerPixel,      // what only the per-pixel techniques use (displacement moves real geometry)
  Classic,       // Blinn-Phong shading's own terms
  Pbr,           // metallic-roughness shading's own terms
};

// A material parameter: its OptionSpec (name = preset key and the CLI's --set name) plus its
// id, the panel section it appears in, when it has an effect, and how it reaches the shader.
struct ParameterSpec : OptionSpec {
  ParamId id = ParamId::Count;
  std::string_view group;
  ParamUse use = ParamUse::Always;
  // The material shader's uniform that receives the value (float for Float, int for Int and
  // Choice, bool for Bool), multiplied by uniformScale (the shader's unit per the table's).
  // Empty for switches that select a shader variant instead (renderer/ShaderVariant.cpp).
  std::string_view uniform;
  double uniformScale = 1.0;
};

std::span<const ParameterSpec> allParameters();
const ParameterSpec& parameterSpec(ParamId id);
std::optional<ParamId> findParameter(std::string_view name);
// The declared default: the one value every caller uses (metrics, samples, tools, tests).
inline double parameterDefault(ParamId id) {
  return parameterSpec(id).defaultValue;
}

// Whether the parameter changes the picture with this technique, shadow mode and shading.
bool parameterInUse(const ParameterSpec& spec, Technique technique, ShadowMode shadows,
                    ShadingModel shading);

// A full set of values indexed by ParamId, initialised to the defaults.
using ParameterValues = std::array<double, kParamCount>;
ParameterValues defaultParameterValues();

}  // namespace relief::core::inline material
