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

// Gradient at x of the rows above per kernel. `rows` are the five rows y-2..y+2 (top first,
// i.e. increasing image row); column(k) is the edge-resolved column for offset k from x.
struct Gradient {
  float dx, dyUp;
};

template <GradientKernel kKernel, class Column>
inline Gradient gradientAt(const float* const rows[5], Column column) {
  const float* up = rows[1];
  const float* mid = rows[2];
  const float* down = rows[3];
  if constexpr (kKernel == GradientKernel::Central) {
    return {0.5f * (mid[column(1)] - mid[column(-1)]), 0.5f * (up[column(0)] - down[column(0)])};
  } else if constexpr (kKernel == GradientKernel::Sobel) {
    const int l = column(-1), c = column(0), r = column(1);
    const float dx = (up[r] + 2.0f * mid[r] + down[r]) - (up[l] + 2.0f * mid[l] + down[l]);
    const float dy = (up[l] + 2.0f * up[c] + up[r]) - (down[l] + 2.0f * down[c] + down[r]);
    return {dx / 8.0f, dy / 8.0f};
  } else if constexpr (kKernel == GradientKernel::Scharr) {
    const int l = column(-1), c = column(0), r = column(1);
    const float dx = (3.0f * up[r] + 10.0f * mid[r] + 3.0f * down[r]) -
                     (3.0f * up[l] + 10.0f * mid[l] + 3.0f * down[l]);
    const float dy = (3.0f * up[l] + 10.0f * up[c] + 3.0f * up[r]) -
                     (3.0f * down[l] + 10.0f * down[c] + 3.0f * down[r]);
    return {dx / 32.0f, dy / 32.0f};
  } else {
    static_assert(kKernel == GradientKernel::Sobel5);
    static constexpr float kSmooth[5] = {1, 4, 6, 4, 1};
    static constexpr float kDerive[5] = {-1, -2, 0, 2, 1};
    float dx = 0.0f, dy = 0.0f;
    for (int j = 0; j < 5; ++j) {
      const float* r = rows[j];
      for (int i = 0; i < 5; ++i) {
        const float h = r[column(i - 2)];
        dx += kSmooth[j] * kDerive[i] * h;
        dy -= kDerive[j] * kSmooth[i] * h;  // rows grow downward; y grows up
      }
    }
    return {dx / 128.0f, dy / 128.0f};
  }
}

// Calls visit(y, x, gradient) for every texel, rows in parallel. Columns two or more texels
// from the edges index the rows directly; only the border goes through the edge table (the
// per-texel table lookups and kernel switch made this loop half the generator's time).
template <GradientKernel kKernel, class Visit>
bool forEachGradientOf(const Plane& plane, EdgeMode edge, const WorkControl& control,
                       Visit& visit) {
  const std::vector<int> xi = edgeIndexTable(plane.width, 2, edge);
  const int interiorEnd = std::max(2, plane.width - 2);
  return parallelFor(
      plane.height,
      [&](int y) {
        const float* rows[5];
        for (int j = 0; j < 5; ++j)
          rows[j] = plane.row(edgeIndex(y + j - 2, plane.height, edge));
        const auto border = [&](int x) {
          visit(y, x, gradientAt<kKernel>(rows, [&](int k) { return xi[std::size_t(x + 2 + k)]; }));
        };
        for (int x = 0; x < std::min(2, plane.width); ++x)
          border(x);
        for (int x = 2; x < interiorEnd; ++x)
          visit(y, x, gradientAt<kKernel>(rows, [x](int k) { return x + k; }));
        for (int x = interiorEnd; x < plane.width; ++x)
          border(x);
      },
      control);
}

template <class Visit>
bool forEachGradient(const Plane& plane, GradientKernel kernel, EdgeMode edge,
                     const WorkControl& control, Visit visit) {
  switch (kernel) {
    case GradientKernel::Central:
      return forEachGradientOf<GradientKernel::Central>(plane, edge, control, visit);
    case GradientKernel::Sobel:
      return forEachGradientOf<GradientKernel::Sobel>(plane, edge, control, visit);
    case GradientKernel::Scharr:
      return forEachGradientOf<GradientKernel::Scharr>(plane, edge, control, visit);
    case GradientKernel::Sobel5:
      return forEachGradientOf<GradientKernel::Sobel5>(plane, edge, control, visit);
  }
  return false;
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
  Image normals = Image::forOverwrite(height.width(), height.height(), 3, ColorSpace::Linear);
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
