// Colour-space tag carried by every Image, and the sRGB transfer functions (IEC 61966-2-1).
// Colour maps are sRGB-encoded; normal, height, AO and roughness maps are linear data.
#pragma once

#include <cmath>
#include <string_view>

namespace relief::core::inline image {

enum class ColorSpace { Linear, Srgb };

constexpr std::string_view colorSpaceName(ColorSpace space) {
  return space == ColorSpace::Srgb ? "srgb" : "linear";
}

inline float srgbToLinear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

inline float linearToSrgb(float linear) {
  return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

}  // namespace relief::core::inline image
