// The parameter table; see Parameters.h.
#include "core/Parameters.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace relief::core {
namespace {

std::vector<ParameterSpec> buildTable() {
  return {
      {ParamId::Tiling,
       "tiling",
       "Tiling",
       "repeats across the mesh UV range",
       "How many times the maps repeat across the mesh's UV range.",
       ParamKind::Float,
       0.1,
       16.0,
       1.0,
       2,
       {}},
      {ParamId::NormalStrength,
       "normalStrength",
       "Normal strength",
       "factor on normal X/Y",
       "Scales the tilt of the normal map (its X and Y) before renormalising; 0 shows the "
       "surface flat, 1 as authored.",
       ParamKind::Float,
       0.0,
       4.0,
       1.0,
       2,
       {}},
      {ParamId::NormalYDown,
       "normalYDown",
       "DirectX normal map (Y down)",
       "switch",
       "Read the normal map's green channel as Y pointing down (DirectX/Unreal convention) "
       "instead of up (OpenGL/Blender/Godot/glTF).",
       ParamKind::Bool,
       0.0,
       1.0,
       0.0,
       0,
       {}},
      {ParamId::Specular,
       "specular",
       "Specular",
       "fraction of the light colour",
       "Strength of the Blinn-Phong highlight.",
       ParamKind::Float,
       0.0,
       1.0,
       0.25,
       2,
       {}},
      {ParamId::Shininess,
       "shininess",
       "Shininess",
       "Blinn-Phong exponent",
       "Sharpness of the highlight: the exponent on N·H. A roughness map, when present, "
       "scales it down per texel.",
       ParamKind::Float,
       1.0,
       256.0,
       32.0,
       0,
       {}},
  };
}

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string lower(std::string_view text) {
  std::string result(text);
  std::transform(result.begin(), result.end(), result.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return result;
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

double sanitizeParameterValue(const ParameterSpec& spec, double value) {
  if (!std::isfinite(value)) {
    return spec.defaultValue;
  }
  value = std::clamp(value, spec.minimum, spec.maximum);
  return spec.kind == ParamKind::Float ? value : std::round(value);
}

Result<double> parseParameterValue(const ParameterSpec& spec, std::string_view text) {
  const std::string word = lower(text);
  if (spec.kind == ParamKind::Bool) {
    if (word == "1" || word == "true" || word == "on" || word == "yes")
      return 1.0;
    if (word == "0" || word == "false" || word == "off" || word == "no")
      return 0.0;
    return makeError(std::string(spec.name) + ": expected true or false, got '" +
                     std::string(text) + "'");
  }
  if (spec.kind == ParamKind::Choice) {
    for (std::size_t i = 0; i < spec.choices.size(); ++i) {
      if (lower(spec.choices[i]) == word)
        return double(i);
    }
    std::string names;
    for (std::string_view choice : spec.choices) {
      names += (names.empty() ? "" : ", ") + std::string(choice);
    }
    return makeError(std::string(spec.name) + ": expected one of " + names + ", got '" +
                     std::string(text) + "'");
  }
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto [last, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || last != end || !std::isfinite(value)) {
    return makeError(std::string(spec.name) + ": '" + std::string(text) + "' is not a number");
  }
  if (value < spec.minimum || value > spec.maximum) {
    return makeError(std::string(spec.name) + ": " + std::string(text) + " is outside " +
                     formatNumber(spec.minimum) + " to " + formatNumber(spec.maximum) + " (" +
                     std::string(spec.unit) + ")");
  }
  if (spec.kind == ParamKind::Int && value != std::round(value)) {
    return makeError(std::string(spec.name) + ": expected a whole number, got " +
                     std::string(text));
  }
  return value;
}

std::string describeParameter(const ParameterSpec& spec) {
  std::string text = std::string(spec.name) + " (" + std::string(spec.unit) + "): ";
  text += std::string(spec.description);
  if (spec.kind == ParamKind::Choice) {
    text += " One of:";
    for (std::string_view choice : spec.choices)
      text += " " + std::string(choice);
    text += "; default " + std::string(spec.choices[std::size_t(spec.defaultValue)]) + ".";
  } else if (spec.kind == ParamKind::Bool) {
    text += std::string(" Default ") + (spec.defaultValue != 0.0 ? "true." : "false.");
  } else {
    text += " Range " + formatNumber(spec.minimum) + " to " + formatNumber(spec.maximum) +
            ", default " + formatNumber(spec.defaultValue) + ".";
  }
  return text;
}

ParameterValues defaultParameterValues() {
  ParameterValues values{};
  for (const ParameterSpec& spec : allParameters()) {
    values[std::size_t(spec.id)] = spec.defaultValue;
  }
  return values;
}

}  // namespace relief::core
