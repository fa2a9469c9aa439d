// MaxMipPyramid; see MaxMipPyramid.h.
#include "core/tracing/MaxMipPyramid.h"

#include "core/base/ParallelFor.h"

#include <algorithm>

namespace relief::core::inline tracing {
namespace {

// The children of cell c of a level of `size` cells built from a level of `childSize`: 2c and
// 2c + 1, and for the last cell every child to the end (an odd count leaves one dangling).
std::pair<int, int> childRange(int c, int size, int childSize) {
  const int first = std::min(2 * c, childSize - 1);
  const int last = c == size - 1 ? childSize - 1 : std::min(2 * c + 1, childSize - 1);
  return {first, last};
}

}  // namespace

MaxMipPyramid buildMaxMipPyramid(const Image& heights, int channel, bool heightIsDepth) {
  MaxMipPyramid pyramid;
  const int width = heights.width();
  const int height = heights.height();
  if (width <= 0 || height <= 0)
    return pyramid;
  const int c = std::clamp(channel, 0, heights.channels() - 1);
  const std::size_t stride = std::size_t(heights.channels());

  // Level 0 reads every texel four times: rows by pointer, the wrap only at the last column.
  // Depths bound 1 - depth, whose maximum is 1 - the minimum depth.
  MaxMipLevel base{width, height, std::vector<float>(std::size_t(width) * std::size_t(height))};
  parallelFor(height, [&](int y) {
    const float* row0 = heights.pixel(0, y) + c;
    const float* row1 = heights.pixel(0, (y + 1) % height) + c;
    float* out = &base.values[std::size_t(y) * std::size_t(width)];
    for (int x = 0; x < width; ++x) {
      const std::size_t here = std::size_t(x) * stride;
      const std::size_t next = x + 1 < width ? here + stride : 0;
      if (heightIsDepth) {
        out[x] =
            1.0f - std::min(std::min(row0[here], row0[next]), std::min(row1[here], row1[next]));
      } else {
        out[x] = std::max(std::max(row0[here], row0[next]), std::max(row1[here], row1[next]));
      }
    }
  });
  pyramid.levels.push_back(std::move(base));

  while (pyramid.levels.back().width > 1 || pyramid.levels.back().height > 1) {
    const MaxMipLevel& child = pyramid.levels.back();
    MaxMipLevel level{std::max(child.width / 2, 1), std::max(child.height / 2, 1), {}};
    level.values.resize(std::size_t(level.width) * std::size_t(level.height));
    parallelFor(level.height, [&](int y) {
      const auto [y0, y1] = childRange(y, level.height, child.height);
      for (int x = 0; x < level.width; ++x) {
        const auto [x0, x1] = childRange(x, level.width, child.width);
        float most = child.at(x0, y0);
        for (int cy = y0; cy <= y1; ++cy) {
          for (int cx = x0; cx <= x1; ++cx)
            most = std::max(most, child.at(cx, cy));
        }
        level.values[std::size_t(y) * std::size_t(level.width) + std::size_t(x)] = most;
      }
    });
    pyramid.levels.push_back(std::move(level));
  }
  return pyramid;
}

}  // namespace relief::core::inline tracing
