// EngineConversion; see EngineConversion.h.
#include "core/exporters/EngineConversion.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline exporters {

double roughnessFromShininess(double shininess) {
  const double alphaSquared = 2.0 / (std::max(shininess, 0.0) + 2.0);
  return std::clamp(std::pow(alphaSquared, 0.25), 0.0, 1.0);
}

Image openGlNormalMap(const Image& normals, bool yDown) {
  if (!yDown || normals.channels() < 2)
    return normals;
  Image flipped = normals;
  for (std::size_t p = 0; p < flipped.pixelCount(); ++p) {
    float& green = flipped.data()[p * std::size_t(flipped.channels()) + 1];
    green = 1.0f - green;
  }
  return flipped;
}

}  // namespace relief::core::inline exporters
