// MapContent; see MapContent.h.
#include "core/material/MapContent.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline material {

bool looksLikeNormalMap(const Image& image) {
  if (image.isEmpty() || image.channels() < 3)
    return false;
  // A grid of at most 64x64 texels is plenty to tell, and costs nothing on a 16k map.
  constexpr int kGrid = 64;
  const int stepX = std::max(1, image.width() / kGrid);
  const int stepY = std::max(1, image.height() / kGrid);
  double sum[3] = {0.0, 0.0, 0.0};
  int count = 0, unit = 0;
  for (int y = stepY / 2; y < image.height(); y += stepY) {
    for (int x = stepX / 2; x < image.width(); x += stepX) {
      double lengthSquared = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double value = image.at(x, y, c);
        sum[c] += value;
        lengthSquared += (2.0 * value - 1.0) * (2.0 * value - 1.0);
      }
      ++count;
      const double length = std::sqrt(lengthSquared);
      unit += length >= 0.8 && length <= 1.2;
    }
  }
  const double meanR = sum[0] / count, meanG = sum[1] / count, meanB = sum[2] / count;
  return std::abs(meanR - 0.5) <= 0.08 && std::abs(meanG - 0.5) <= 0.08 && meanB >= 0.7 &&
         unit >= 0.9 * count;
}

}  // namespace relief::core::inline material
