// The material parameters, declared once: name (the preset key and the CLI's --set name),
// label, unit, range and default. The UI builds its controls from this table, presets store
// values under these names and the CLI parses them, so nothing is declared twice.
#pragma once

#include "core/OptionSpec.h"
#include "core/Result.h"

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace relief::core {

enum class ParamId {
  // Relief
  HeightScale,
  HeightBias,
  HeightIsDepth,
  HeightInNormalAlpha,
  // Sampling
  MinSamples,
  MaxSamples,
  RefinementSteps,
  LodFade,
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
  // Surface
  NormalStrength,
  NormalYDown,
  Specular,
  Shininess,
  Count,
};

// Values of the Choice parameters.
enum class ShadowMode { Off, Hard, Soft };
enum class UvEdge { Repeat, Clamp };

constexpr std::size_t kParamCount = std::size_t(ParamId::Count);

// A material parameter: its OptionSpec (name = preset key and the CLI's --set name) plus its
// id and the panel section it appears in.
struct ParameterSpec : OptionSpec {
  ParamId id = ParamId::Count;
  std::string_view group;
};

std::span<const ParameterSpec> allParameters();
const ParameterSpec& parameterSpec(ParamId id);
std::optional<ParamId> findParameter(std::string_view name);

// A full set of values indexed by ParamId, initialised to the defaults.
using ParameterValues = std::array<double, kParamCount>;
ParameterValues defaultParameterValues();

}  // namespace relief::core
