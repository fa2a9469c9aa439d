// NormalFromHeight; see NormalFromHeight.h.
#include "core/generators/NormalFromHeight.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace relief::core::inline generators {
namespace {

// A single-channel view of the first channel, contiguous (copied only when needed).
struct Plane {
  std::vector<float> storage;
  const float* data = nullptr;
  int width = 0;
  int height = 0;
  const float* row(int y) const { return data + std::size_t(y) * std::size_t(width); }
};

Plane firstChannel(const Image& image) {
  Plane plane;
  plane.width = image.width();
  plane.height = image.height();
  if (image.channels() == 1) {
    plane.data = image.data();
    return plane;
  }
  plane.storage.resize(image.pixelCount());
  for (std::size_t i = 0; i < image.pixelCount(); ++i) {
    plane.storage[i] = image.data()[i * std::size_t(image.channels())];
  }
  plane.data = plane.storage.data();
  return plane;
}

// Gradient at x of the rows above (rows[0..]) per kernel. `rows` are the five rows y-2..y+2
// (top first, i.e. increasing image row), `xi` the edge-resolved column table with margin 2.
struct Gradient {
  float dx, dyUp;
};

inline Gradient gradientAt(GradientKernel kernel, const float* const rows[5], const int* xi,
                           int x) {
  // xi[x + 2 + k] is the column for offset k.
  const int* c = xi + x + 2;
  const float* up = rows[1];
  const float* mid = rows[2];
  const float* down = rows[3];
  switch (kernel) {
    case GradientKernel::Central:
      return {0.5f * (mid[c[1]] - mid[c[-1]]), 0.5f * (up[c[0]] - down[c[0]])};
    case GradientKernel::Sobel: {
      const float dx = (up[c[1]] + 2.0f * mid[c[1]] + down[c[1]]) -
                       (up[c[-1]] + 2.0f * mid[c[-1]] + down[c[-1]]);
      const float dy =
          (up[c[-1]] + 2.0f * up[c[0]] + up[c[1]]) - (down[c[-1]] + 2.0f * down[c[0]] + down[c[1]]);
      return {dx / 8.0f, dy / 8.0f};
    }
    case GradientKernel::Scharr: {
      const float dx = (3.0f * up[c[1]] + 10.0f * mid[c[1]] + 3.0f * down[c[1]]) -
                       (3.0f * up[c[-1]] + 10.0f * mid[c[-1]] + 3.0f * down[c[-1]]);
      const float dy = (3.0f * up[c[-1]] + 10.0f * up[c[0]] + 3.0f * up[c[1]]) -
                       (3.0f * down[c[-1]] + 10.0f * down[c[0]] + 3.0f * down[c[1]]);
      return {dx / 32.0f, dy / 32.0f};
    }
    case GradientKernel::Sobel5: {
      static constexpr float kSmooth[5] = {1, 4, 6, 4, 1};
      static constexpr float kDerive[5] = {-1, -2, 0, 2, 1};
      float dx = 0.0f, dy = 0.0f;
      for (int j = 0; j < 5; ++j) {
        const float* r = rows[j];
        for (int i = 0; i < 5; ++i) {
          const float h = r[c[i - 2]];
          dx += kSmooth[j] * kDerive[i] * h;
          dy -= kDerive[j] * kSmooth[i] * h;  // rows grow downward; y grows up
        }
      }
      return {dx / 128.0f, dy / 128.0f};
    }
  }
  return {0.0f, 0.0f};
}

// Calls visit(y, x, gradient) for every texel, rows in parallel.
template <class Visit>
bool forEachGradient(const Plane& plane, GradientKernel kernel, EdgeMode edge,
                     const WorkControl& control, Visit visit) {
  const std::vector<int> xi = edgeIndexTable(plane.width, 2, edge);
  return parallelFor(
      plane.height,
      [&](int y) {
        const float* rows[5];
        for (int j = 0; j < 5; ++j)
          rows[j] = plane.row(edgeIndex(y + j - 2, plane.height, edge));
        for (int x = 0; x < plane.width; ++x)
          visit(y, x, gradientAt(kernel, rows, xi.data(), x));
      },
      control);
}

}  // namespace

Image heightGradient(const Image& height, GradientKernel kernel, EdgeMode edge,
                     const WorkControl& control) {
  const Plane plane = firstChannel(height);
  Image gradient(height.width(), height.height(), 2);
  forEachGradient(plane, kernel, edge, control, [&](int y, int x, Gradient g) {
    float* out = gradient.pixel(x, y);
    out[0] = g.dx;
    out[1] = g.dyUp;
  });
  return gradient;
}

Image normalMapFromHeight(const Image& height, const NormalFromHeightOptions& options,
                          const WorkControl& control) {
  const float ySign = options.convention == NormalConvention::DirectX ? -1.0f : 1.0f;
  Image normals(height.width(), height.height(), 3, ColorSpace::Linear);
  normals.setSourceBitsPerChannel(16);
  const auto writeNormal = [&](int y, int x, float dx, float dyUp) {
    const float nx = -options.strength * dx;
    const float ny = -options.strength * dyUp * ySign;
    const float inverseLength = 1.0f / std::sqrt(nx * nx + ny * ny + 1.0f);
    float* out = normals.pixel(x, y);
    out[0] = nx * inverseLength * 0.5f + 0.5f;
    out[1] = ny * inverseLength * 0.5f + 0.5f;
    out[2] = inverseLength * 0.5f + 0.5f;
  };

  float weightSum = 0.0f;
  for (float w : options.detailWeights)
    weightSum += std::max(w, 0.0f);
  const bool singleScale =
      weightSum <= 0.0f || weightSum == std::max(options.detailWeights[0], 0.0f);
  if (singleScale) {
    // The common case: no intermediate buffers, one pass.
    forEachGradient(firstChannel(height), options.kernel, options.edge, control,
                    [&](int y, int x, Gradient g) { writeNormal(y, x, g.dx, g.dyUp); });
    return normals;
  }

  // Multi-scale detail: the weighted mean of the gradients of the blur levels.
  Image sum(height.width(), height.height(), 2);
  int levels = 0;
  for (float w : options.detailWeights)
    levels += w > 0.0f;
  int level = 0;
  for (std::size_t l = 0; l < options.detailWeights.size(); ++l) {
    const float weight = options.detailWeights[l] / weightSum;
    if (!(weight > 0.0f))
      continue;
    const WorkControl part{[&](double f) { control.report((double(level) + f) / levels); },
                           control.cancel};
    const Image source =
        kDetailSigmas[l] > 0.0
            ? gaussianBlur(height, kDetailSigmas[l] * options.texelScale, options.edge, part)
            : height;
    forEachGradient(firstChannel(source), options.kernel, options.edge, part,
                    [&](int y, int x, Gradient g) {
                      float* out = sum.pixel(x, y);
                      out[0] += weight * g.dx;
                      out[1] += weight * g.dyUp;
                    });
    ++level;
    if (control.cancelled())
      return normals;
  }
  parallelFor(height.height(), [&](int y) {
    for (int x = 0; x < height.width(); ++x)
      writeNormal(y, x, sum.at(x, y, 0), sum.at(x, y, 1));
  });
  return normals;
}

}  // namespace relief::core::inline generators
