// The material parameters, declared once: name (the preset key and the CLI's --set name),
// label, unit, range and default. The UI builds its controls from this table, presets store
// values under these names and the CLI parses them, so nothing is declared twice.
#pragma once

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

enum class ParamKind { Float, Int, Bool, Choice };

struct ParameterSpec {
  ParamId id;
  std::string_view name;         // preset key, CLI --set name
  std::string_view label;        // shown next to the control
  std::string_view group;        // the panel section it appears in
  std::string_view unit;         // stated in tooltips and --help
  std::string_view description;  // what it does, for tooltips
  ParamKind kind;
  double minimum;
  double maximum;
  double defaultValue;
  int decimals;                           // shown in spin boxes (0 for Int, Bool, Choice)
  std::vector<std::string_view> choices;  // names of Choice values 0..n-1
};

std::span<const ParameterSpec> allParameters();
const ParameterSpec& parameterSpec(ParamId id);
std::optional<ParamId> findParameter(std::string_view name);

// Clamps to the declared range and rounds Int, Bool and Choice values to whole numbers.
double sanitizeParameterValue(const ParameterSpec& spec, double value);

// Parses a value as written on a command line or in a text field: a number, true/false/on/off
// for Bool, a choice name for Choice. Out-of-range or unparsable text is an error naming the
// parameter and its range.
Result<double> parseParameterValue(const ParameterSpec& spec, std::string_view text);

// "Tiling (repeats): ..., 0.1 to 16, default 1" — for --help and tooltips.
std::string describeParameter(const ParameterSpec& spec);

// A full set of values indexed by ParamId, initialised to the defaults.
using ParameterValues = std::array<double, kParamCount>;
ParameterValues defaultParameterValues();

}  // namespace relief::core
