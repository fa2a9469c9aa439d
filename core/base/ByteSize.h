// Sizes as people write them in budgets ("6MB", "512 KiB", "1.5 GB", "700000"): decimal units
// (kB, MB, GB: powers of 1000, as download and disk budgets are quoted) and binary ones (KiB, MiB,
// GiB: powers of 1024), case-insensitive, a bare number being bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace relief::core::inline base {

// Empty for text that is not a size, a negative or zero size, or one beyond 2^63 bytes.
std::optional<std::uint64_t> parseByteSize(std::string_view text);
// "5.87 MB", "812.4 kB", "950 bytes": three significant digits in decimal units.
std::string describeByteSize(std::uint64_t bytes);

}  // namespace relief::core::base
