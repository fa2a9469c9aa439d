// NormalFromHeight; see NormalFromHeight.h.
#include "core/generators/NormalFromHeight.h"

#include <algorithm>
#include <cmath>

namespace relief::core {
namespace {

int edgeIndex(int i, int size, EdgeMode edge) {
  if (edge == EdgeMode::Wrap)
    return (i % size + size) % size;
  return i < 0 ? 0 : (i >= size ? size - 1 : i);
}

}  // namespace

Image normalMapFromHeight(const Image& height, const NormalFromHeightOptions& options) {
  const int width = height.width();
  const int rows = height.height();
  // Texels between the two samples: 2 inside and when wrapping; 1 at a clamped border (a
  // one-sided difference); never 0, even for a 1-texel-wide map.
  const auto spacing = [&](int before, int after) {
    return options.edge == EdgeMode::Wrap ? 2.0f : float(std::max(after - before, 1));
  };
  Image normals(width, rows, 3, ColorSpace::Linear);
  for (int y = 0; y < rows; ++y) {
    const int up = edgeIndex(y - 1, rows, options.edge);
    const int down = edgeIndex(y + 1, rows, options.edge);
    for (int x = 0; x < width; ++x) {
      const int left = edgeIndex(x - 1, width, options.edge);
      const int right = edgeIndex(x + 1, width, options.edge);
      const float dhdx = (height.at(right, y, 0) - height.at(left, y, 0)) / spacing(left, right);
      // Image rows grow downward while v grows upward: dh/dv = -dh/drow.
      const float dhdy = (height.at(x, up, 0) - height.at(x, down, 0)) / spacing(up, down);
      const float nx = -options.strength * dhdx;
      const float ny = -options.strength * dhdy;
      const float inverseLength = 1.0f / std::sqrt(nx * nx + ny * ny + 1.0f);
      float* out = normals.pixel(x, y);
      out[0] = nx * inverseLength * 0.5f + 0.5f;
      out[1] = ny * inverseLength * 0.5f + 0.5f;
      out[2] = inverseLength * 0.5f + 0.5f;
    }
  }
  return normals;
}

}  // namespace relief::core
