// ByteSize; see ByteSize.h.
#include "core/base/ByteSize.h"

#include "core/base/Text.h"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace relief::core::inline base {

std::optional<std::uint64_t> parseByteSize(std::string_view text) {
  while (!text.empty() && text.front() == ' ')
    text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ')
    text.remove_suffix(1);
  double number = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error != std::errc() || end == text.data())
    return std::nullopt;
  std::string_view unitText(end, std::size_t(text.data() + text.size() - end));
  while (!unitText.empty() && unitText.front() == ' ')
    unitText.remove_prefix(1);
  const std::string unit = lowerCase(unitText);
  constexpr std::array<std::pair<std::string_view, double>, 9> kUnits = {{
      {"", 1.0},
      {"b", 1.0},
      {"bytes", 1.0},
      {"kb", 1e3},
      {"mb", 1e6},
      {"gb", 1e9},
      {"kib", 1024.0},
      {"mib", 1024.0 * 1024.0},
      {"gib", 1024.0 * 1024.0 * 1024.0},
  }};
  for (const auto& [name, scale] : kUnits) {
    if (unit != name)
      continue;
    const double bytes = std::floor(number * scale);
    if (!std::isfinite(bytes) || bytes < 1.0 || bytes > 9.2e18)
      return std::nullopt;
    return std::uint64_t(bytes);
  }
  return std::nullopt;
}

std::string describeByteSize(std::uint64_t bytes) {
  char text[32];
  if (bytes < 1000) {
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
    return text;
  }
  constexpr std::array<std::pair<double, const char*>, 3> kUnits = {
      {{1e9, "GB"}, {1e6, "MB"}, {1e3, "kB"}}};
  for (const auto& [scale, name] : kUnits) {
    const double value = double(bytes) / scale;
    if (value < 1.0)
      continue;
    const int decimals = value >= 100.0 ? 1 : 2;
    std::snprintf(text, sizeof text, "%.*f %s", decimals, value, name);
    return text;
  }
  return {};  // not reached: bytes >= 1000 is at least 1 kB
}

}  // namespace relief::core::base
