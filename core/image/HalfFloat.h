// IEEE 754 binary16 ("half") conversions, for the half-float block formats (BC6H) and the
// errors measured on them. OpenEXR's Imath::half does the same, but it is a dependency of the
// image readers only; the codecs keep to the standard library.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace relief::core::inline image {

inline constexpr float kMaxHalf = 65504.0f;  // the largest finite half

// Rounded to the nearest half (ties to even); beyond kMaxHalf gives infinity, NaN a quiet NaN.
inline std::uint16_t floatToHalf(float value) {
  std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
  const auto sign = std::uint16_t((bits >> 16) & 0x8000u);
  bits &= 0x7FFFFFFFu;
  if (bits >= 0x7F800000u)  // infinity or NaN
    return std::uint16_t(sign | (bits > 0x7F800000u ? 0x7E00u : 0x7C00u));
  if (bits >= 0x477FF000u)  // 65520 and above round to infinity
    return std::uint16_t(sign | 0x7C00u);
  if (bits < 0x38800000u) {  // below 2^-14: a subnormal half, a multiple of 2^-24
    const float scaled = std::bit_cast<float>(bits) * 16777216.0f;
    return std::uint16_t(sign | std::uint16_t(std::nearbyint(scaled)));
  }
  // Rebias the exponent (127 to 15) and round the 23-bit mantissa to 10 bits, ties to even; a
  // carry out of the mantissa correctly bumps the exponent.
  std::uint32_t half = (bits - 0x38000000u) >> 13;
  const std::uint32_t rest = bits & 0x1FFFu;
  if (rest > 0x1000u || (rest == 0x1000u && (half & 1u)))
    ++half;
  return std::uint16_t(sign | half);
}

inline float halfToFloat(std::uint16_t half) {
  const std::uint32_t sign = std::uint32_t(half & 0x8000u) << 16;
  const std::uint32_t exponent = (half >> 10) & 0x1Fu;
  const std::uint32_t mantissa = half & 0x3FFu;
  if (exponent == 0) {
    const float magnitude = float(mantissa) * (1.0f / 16777216.0f);
    return sign ? -magnitude : magnitude;
  }
  if (exponent == 31)
    return std::bit_cast<float>(sign | 0x7F800000u | mantissa << 13);
  return std::bit_cast<float>(sign | (exponent + 112u) << 23 | mantissa << 13);
}

}  // namespace relief::core::inline image
