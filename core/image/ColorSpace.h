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

// The colour space of an OpenImageIO "oiio:ColorSpace" name, as image files carry it (PNG text,
// or what a reader derives from the file): sRGB and gamma curves ("Gamma2.2") are sRGB-encoded
// colour, anything else ("linear", "Linear", a float file's scene-linear) is linear data.
constexpr ColorSpace colorSpaceFromOiioName(std::string_view name) {
  return (name == "sRGB" || name.substr(0, 5) == "Gamma") ? ColorSpace::Srgb : ColorSpace::Linear;
}

inline float srgbToLinear(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

inline float linearToSrgb(float linear) {
  return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

}  // namespace relief::core::inline image
