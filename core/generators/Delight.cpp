// Delighting; see Delight.h.
#include "core/generators/Delight.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline generators {

DelightResult delight(const Image& color, const DelightOptions& options,
                      const WorkControl& control) {
  DelightResult result;
  const Image light =
      gaussianBlur(luminance(color), options.radius * options.texelScale, options.edge, control);
  double mean = 0.0;
  for (std::size_t i = 0; i < light.pixelCount(); ++i)
    mean += light.data()[i];
  mean /= double(std::max<std::size_t>(light.pixelCount(), 1));
  result.albedo = color;
  if (mean <= 1e-6)
    return result;  // black: no light to remove
  double low = 1e30, high = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < light.pixelCount(); ++i) {
    const double relative = light.data()[i] / mean;
    low = std::min(low, relative);
    high = std::max(high, relative);
    squares += (relative - 1.0) * (relative - 1.0);
  }
  result.lightLow = low;
  result.lightHigh = high;
  result.lightRms = std::sqrt(squares / double(light.pixelCount()));

  if (options.strength <= 0.0)
    return result;  // the photo as it is (no round trip through linear)
  const bool srgb = color.colorSpace() == ColorSpace::Srgb;
  const int colourChannels = std::min(color.channels(), 3);  // alpha is not light
  Image& albedo = result.albedo;
  parallelFor(
      color.height(),
      [&](int y) {
        for (int x = 0; x < color.width(); ++x) {
          // A floor on the light: a texel in near-black shadow holds too little of its colour
          // to be lifted 20 times without its noise.
          const double relative = std::max(double(light.at(x, y, 0)) / mean, 0.05);
          const float factor = float(std::pow(relative, -options.strength));
          float* texel = albedo.pixel(x, y);
          for (int c = 0; c < colourChannels; ++c) {
            const float linear = (srgb ? srgbToLinear(texel[c]) : texel[c]) * factor;
            const float clamped = std::clamp(linear, 0.0f, 1.0f);
            texel[c] = srgb ? linearToSrgb(clamped) : clamped;
          }
        }
      },
      control);
  return result;
}

}  // namespace relief::core::inline generators
