// OptionSpec; see OptionSpec.h.
#include "core/base/OptionSpec.h"

#include "core/base/Text.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace relief::core::inline base {
namespace {

std::string formatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

OptionSpec numberOption(std::string_view name, std::string_view label, std::string_view unit,
                        double minimum, double maximum, double defaultValue, int decimals,
                        std::string_view description) {
  return {name,    label,   unit,         description, ParamKind::Float,
          minimum, maximum, defaultValue, decimals,    {}};
}

OptionSpec integerOption(std::string_view name, std::string_view label, std::string_view unit,
                         int minimum, int maximum, int defaultValue, std::string_view description) {
  return {name,
          label,
          unit,
          description,
          ParamKind::Int,
          double(minimum),
          double(maximum),
          double(defaultValue),
          0,
          {}};
}

OptionSpec flagOption(std::string_view name, std::string_view label, bool defaultValue,
                      std::string_view description) {
  return {name, label, "switch", description, ParamKind::Bool, 0.0, 1.0, defaultValue ? 1.0 : 0.0,
          0,    {}};
}

OptionSpec choiceOption(std::string_view name, std::string_view label,
                        std::vector<std::string_view> choices, int defaultValue,
                        std::string_view description) {
  const double last = double(choices.size() - 1);
  return {name,
          label,
          "choice",
          description,
          ParamKind::Choice,
          0.0,
          last,
          double(defaultValue),
          0,
          std::move(choices)};
}

double sanitizeOptionValue(const OptionSpec& spec, double value) {
  if (!std::isfinite(value))
    return spec.defaultValue;
  value = std::clamp(value, spec.minimum, spec.maximum);
  return spec.kind == ParamKind::Float ? value : std::round(value);
}

Result<double> parseOptionValue(const OptionSpec& spec, std::string_view text) {
  const std::string word = lowerCase(text);
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
      if (lowerCase(spec.choices[i]) == word)
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

std::string describeOption(const OptionSpec& spec) {
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

std::string formatOptionValue(const OptionSpec& spec, double value) {
  switch (spec.kind) {
    case ParamKind::Bool:
      return value != 0.0 ? "true" : "false";
    case ParamKind::Choice:
      return std::string(spec.choices[std::size_t(std::clamp(value, 0.0, spec.maximum))]);
    case ParamKind::Float:
    case ParamKind::Int:
      return formatNumber(value);
  }
  return formatNumber(value);  // not reached: every kind is handled above
}

}  // namespace relief::core::inline base
