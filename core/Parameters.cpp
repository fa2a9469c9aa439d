// The parameter table; see Parameters.h. Every number an artist can tune is declared here
// once, with the reference it comes from where there is one.
#include "core/Parameters.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace relief::core {
namespace {

constexpr std::string_view kRelief = "Relief";
constexpr std::string_view kSampling = "Sampling";
constexpr std::string_view kShadows = "Self-shadowing";
constexpr std::string_view kMapping = "Mapping";
constexpr std::string_view kSurface = "Surface";

ParameterSpec number(ParamId id, std::string_view name, std::string_view label,
                     std::string_view group, std::string_view unit, double minimum, double maximum,
                     double defaultValue, int decimals, std::string_view description) {
  return {id,      name,    label,        group,    unit, description, ParamKind::Float,
          minimum, maximum, defaultValue, decimals, {}};
}

ParameterSpec integer(ParamId id, std::string_view name, std::string_view label,
                      std::string_view group, std::string_view unit, int minimum, int maximum,
                      int defaultValue, std::string_view description) {
  return {id,
          name,
          label,
          group,
          unit,
          description,
          ParamKind::Int,
          double(minimum),
          double(maximum),
          double(defaultValue),
          0,
          {}};
}

ParameterSpec flag(ParamId id, std::string_view name, std::string_view label,
                   std::string_view group, bool defaultValue, std::string_view description) {
  return {id,
          name,
          label,
          group,
          "switch",
          description,
          ParamKind::Bool,
          0.0,
          1.0,
          defaultValue ? 1.0 : 0.0,
          0,
          {}};
}

ParameterSpec choice(ParamId id, std::string_view name, std::string_view label,
                     std::string_view group, std::vector<std::string_view> choices,
                     int defaultValue, std::string_view description) {
  const double last = double(choices.size() - 1);
  return {id,
          name,
          label,
          group,
          "choice",
          description,
          ParamKind::Choice,
          0.0,
          last,
          double(defaultValue),
          0,
          std::move(choices)};
}

std::vector<ParameterSpec> buildTable() {
  return {
      number(ParamId::HeightScale, "heightScale", "Height scale", kRelief,
             "UV units (fractions of the texture width)", 0.0, 0.25, 0.04, 3,
             "Depth of the relief: heights 0..1 span this many texture widths. The surface "
             "height is h * heightScale + heightBias (references 000 and 004)."),
      number(ParamId::HeightBias, "heightBias", "Height bias", kRelief, "UV units", -0.25, 0.25,
             -0.04, 3,
             "Moves the relief relative to the mesh surface (the reference plane of the "
             "marching techniques). -heightScale puts the top (h = 1) on the surface, as in "
             "POM; -heightScale/2 centres it, as in reference 004 (h * 0.04 - 0.02)."),
      flag(ParamId::HeightIsDepth, "heightIsDepth", "Height map is a depth map", kRelief, false,
           "Read the height map as depth (white = deepest), as some tools export it."),
      flag(ParamId::HeightInNormalAlpha, "heightInNormalAlpha", "Height in normal map alpha",
           kRelief, false,
           "Take the height from the normal map's alpha channel instead of the height map "
           "(the packed layout of references 001 and 003)."),
      integer(ParamId::MinSamples, "minSamples", "Min samples", kSampling, "samples", 1, 256, 8,
              "Height samples along the view ray when looking straight at the surface; the "
              "count grows toward maxSamples as the view grazes (reference 001)."),
      integer(ParamId::MaxSamples, "maxSamples", "Max samples", kSampling, "samples", 1, 256, 32,
              "Height samples along the view ray at grazing angles (reference 001). More "
              "samples catch thinner features and cost more."),
      integer(ParamId::RefinementSteps, "refinementSteps", "Refinement steps", kSampling,
              "binary search steps", 0, 16, 5,
              "Relief mapping only: binary search steps after the linear search; each halves "
              "the remaining error."),
      number(ParamId::LodFade, "lodFade", "Fade at mip level", kSampling, "mip levels", 0.0, 12.0,
             0.0, 1,
             "Fades the relief out to plain normal mapping where the height map is sampled at "
             "this mip level (far away or at grazing angles), over the level before it. Saves "
             "the marching cost where it cannot be seen. 0 never fades."),
      choice(ParamId::ShadowMode, "shadowMode", "Shadows", kShadows, {"off", "hard", "soft"}, 2,
             "Self-shadowing by marching from the visible point toward the light (reference "
             "003, 1.3): hard is lit or shadowed, soft estimates a penumbra (Tatarchuk)."),
      number(ParamId::ShadowStrength, "shadowStrength", "Shadow strength", kShadows,
             "fraction of direct light removed", 0.0, 1.0, 0.8, 2,
             "How dark self-shadows are: 0 has no effect, 1 removes all direct light."),
      integer(ParamId::ShadowSamples, "shadowSamples", "Shadow samples", kShadows, "samples", 1,
              128, 16, "Height samples along the ray toward the light."),
      number(ParamId::ShadowSoftness, "shadowSoftness", "Light size", kShadows,
             "degrees (angular diameter of the light)", 0.0, 45.0, 8.0, 1,
             "Soft shadows: the apparent size of the light. Larger lights give wider "
             "penumbras; 0 gives hard edges."),
      flag(ParamId::ShadowLimit, "shadowLimit", "Limit shadow length", kShadows, false,
           "Welsh's offset limit applied to the light ray (reference 003, 1.3): the light ray "
           "climbs as if the light were at least 45 degrees high, so shadows of a low light "
           "stay short instead of stretching across the surface. Off is physically exact."),
      number(ParamId::Tiling, "tiling", "Tiling", kMapping, "repeats across the mesh UV range", 0.1,
             16.0, 1.0, 2, "How many times the maps repeat across the mesh's UV range."),
      choice(ParamId::UvEdge, "uvEdge", "UV edge", kMapping, {"repeat", "clamp"}, 0,
             "repeat: the relief continues across the mesh's UV border. clamp: texels "
             "displaced outside the UV range are discarded, so a plane shows the relief's "
             "silhouette at its edges."),
      flag(ParamId::DepthOffset, "depthOffset", "Write displaced depth", kMapping, false,
           "Write the depth of the displaced surface (gl_FragDepth), so it meets other "
           "geometry where the relief really is. Disables early depth testing."),
      number(ParamId::NormalStrength, "normalStrength", "Normal strength", kSurface,
             "factor on normal X/Y", 0.0, 4.0, 1.0, 2,
             "Scales the tilt of the normal map (its X and Y) before renormalising; 0 shows "
             "the surface flat, 1 as authored."),
      flag(ParamId::NormalYDown, "normalYDown", "DirectX normal map (Y down)", kSurface, false,
           "Read the normal map's green channel as Y pointing down (DirectX/Unreal "
           "convention) instead of up (OpenGL/Blender/Godot/glTF)."),
      number(ParamId::Specular, "specular", "Specular", kSurface, "fraction of the light colour",
             0.0, 1.0, 0.25, 2, "Strength of the Blinn-Phong highlight."),
      number(ParamId::Shininess, "shininess", "Shininess", kSurface, "Blinn-Phong exponent", 1.0,
             256.0, 32.0, 0,
             "Sharpness of the highlight: the exponent on N.H. A roughness map, when present, "
             "scales it down per texel."),
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
