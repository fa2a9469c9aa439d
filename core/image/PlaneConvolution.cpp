// PlaneConvolution; see PlaneConvolution.h.
#include "core/image/PlaneConvolution.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <cstddef>

namespace relief::core::inline image {

// Rows go through a padded copy and columns accumulate whole rows, so the inner loops run over
// contiguous floats without an edge test per tap and vectorise. A clamp per tap (the obvious
// loop) kept SSIM's blur from vectorising: it was half of `compare`'s time on a 2048^2 map.
void convolvePlane(const float* plane, float* out, int width, int height,
                   const std::vector<float>& kernel, bool alongRows) {
  const int radius = int(kernel.size() / 2);
  const auto row = [&](int y) { return plane + std::size_t(y) * std::size_t(width); };
  parallelFor(height, [&](int y) {
    float* target = out + std::size_t(y) * std::size_t(width);
    if (alongRows) {
      std::vector<float> padded(std::size_t(width + 2 * radius));
      const float* source = row(y);
      for (int i = 0; i < width + 2 * radius; ++i)
        padded[std::size_t(i)] = source[std::clamp(i - radius, 0, width - 1)];
      for (int x = 0; x < width; ++x) {
        float sum = 0.0f;
        for (std::size_t k = 0; k < kernel.size(); ++k)
          sum += kernel[k] * padded[std::size_t(x) + k];
        target[x] = sum;
      }
    } else {
      std::fill(target, target + width, 0.0f);
      for (int k = -radius; k <= radius; ++k) {
        const float weight = kernel[std::size_t(k + radius)];
        const float* source = row(std::clamp(y + k, 0, height - 1));
        for (int x = 0; x < width; ++x)
          target[x] += weight * source[x];
      }
    }
  });
}

}  // namespace relief::core::inline image
