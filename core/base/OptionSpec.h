// OptionSpec: how a tunable number is declared once — name (preset key, CLI option), label,
// unit, range, default and description — so the GUI builds its control, presets store it and the
// CLI parses it from the same table. Material parameters (Parameters.h) and generator options
// (generators/Generators.h) are both lists of these.
#pragma once

#include "core/base/Result.h"

#include <string>
#include <string_view>
#include <vector>

namespace relief::core::inline base {

enum class ParamKind { Float, Int, Bool, Choice };

struct OptionSpec {
  std::string_view name;         // preset key, CLI option name
  std::string_view label;        // shown next to the control
  std::string_view unit;         // stated in tooltips and --help
  std::string_view description;  // what it does, for tooltips
  ParamKind kind = ParamKind::Float;
  double minimum = 0.0;
  double maximum = 1.0;
  double defaultValue = 0.0;
  int decimals = 2;                       // shown in spin boxes (0 for Int, Bool, Choice)
  std::vector<std::string_view> choices;  // names of Choice values 0..n-1
};

OptionSpec numberOption(std::string_view name, std::string_view label, std::string_view unit,
                        double minimum, double maximum, double defaultValue, int decimals,
                        std::string_view description);
OptionSpec integerOption(std::string_view name, std::string_view label, std::string_view unit,
                         int minimum, int maximum, int defaultValue, std::string_view description);
OptionSpec flagOption(std::string_view name, std::string_view label, bool defaultValue,
                      std::string_view description);
OptionSpec choiceOption(std::string_view name, std::string_view label,
                        std::vector<std::string_view> choices, int defaultValue,
                        std::string_view description);

// Clamps to the declared range and rounds Int, Bool and Choice values to whole numbers;
// non-finite values become the default.
double sanitizeOptionValue(const OptionSpec& spec, double value);

// Parses a value as written on a command line or in a text field: a number, true/false/on/off
// for Bool, a choice name for Choice. Out-of-range or unparsable text is an error naming the
// option and its range.
Result<double> parseOptionValue(const OptionSpec& spec, std::string_view text);

// "name (unit): description Range a to b, default c." — for --help and tooltips.
std::string describeOption(const OptionSpec& spec);

// The value as text for a preset or a command line: a choice name, true/false, or a number.
std::string formatOptionValue(const OptionSpec& spec, double value);

}  // namespace relief::core::inline base
