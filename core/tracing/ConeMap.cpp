// ConeMap; see ConeMap.h.
#include "core/tracing/ConeMap.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace relief::core::inline tracing {
namespace {

// The cells around a cell bounded by their gradient rather than by their maxima: a cell k
// cells away rises over a cell's lowest corner by up to (k + 2) gradients, where the gradient
// bound says k, so the near square is what keeps cones on smooth slopes wide; a larger one lets
// one steep feature narrow more cones around it. Three keeps the cones on smooth fields at
// about 0.6 of the widest.
constexpr int kNearReach = 3;

// Shells grow by this factor (at least one cell): a shell's cells are bounded at its inner
// distance, so the ratio of inner to outer radius is what a cone loses to the shells.
constexpr double kShellGrowth = 1.25;

// The shells from this distance out are bounded over blocks of kBlock x kBlock cells.
constexpr int kBlock = 4;
constexpr int kCoarseFrom = 16;

// A running maximum over windows of 2 * reach + 1 values of a circular sequence of n values
// read and written with a stride (a row or a column of a map), by van Herk and Gil-Werman's
// method: the maximum over blocks of the window's length from the left (`ahead`) and from the
// right (`behind`) make every window two lookups, whatever its length. Written here because
// OpenImageIO's dilate visits the whole window at every texel, which at the radii the cones
// reach (hundreds of texels) is thousands of times slower.
void circularWindowMax(const float* in, float* out, std::ptrdiff_t stride, int n, int reach,
                       std::vector<float>& extended, std::vector<float>& ahead,
                       std::vector<float>& behind) {
  const int window = 2 * reach + 1;
  if (window >= n) {
    float most = in[0];
    for (int i = 1; i < n; ++i)
      most = std::max(most, in[std::ptrdiff_t(i) * stride]);
    for (int i = 0; i < n; ++i)
      out[std::ptrdiff_t(i) * stride] = most;
    return;
  }
  // The sequence unrolled by `reach` either side: window i of the result is extended[i, i + w).
  const int length = n + 2 * reach;
  extended.resize(std::size_t(length));
  ahead.resize(std::size_t(length));
  behind.resize(std::size_t(length));
  for (int i = 0; i < length; ++i)
    extended[std::size_t(i)] = in[std::ptrdiff_t(((i - reach) % n + n) % n) * stride];
  for (int i = 0; i < length; ++i) {
    ahead[std::size_t(i)] = i % window == 0
                                ? extended[std::size_t(i)]
                                : std::max(ahead[std::size_t(i) - 1], extended[std::size_t(i)]);
  }
  for (int i = length - 1; i >= 0; --i) {
    behind[std::size_t(i)] = (i % window == window - 1 || i == length - 1)
                                 ? extended[std::size_t(i)]
                                 : std::max(behind[std::size_t(i) + 1], extended[std::size_t(i)]);
  }
  for (int i = 0; i < n; ++i) {
    out[std::ptrdiff_t(i) * stride] =
        std::max(behind[std::size_t(i)], ahead[std::size_t(i + window - 1)]);
  }
}

// Replaces `values` (width x height, repeating) by its maximum over the square of cells within
// `reach` of each (rows, then columns).
void squareMax(std::vector<float>& values, std::vector<float>& scratch, int width, int height,
               int reach) {
  scratch.resize(values.size());
  parallelFor(height, [&](int y) {
    thread_local std::vector<float> extended, ahead, behind;
    const std::size_t row = std::size_t(y) * std::size_t(width);
    circularWindowMax(&values[row], &scratch[row], 1, width, reach, extended, ahead, behind);
  });
  parallelFor(width, [&](int x) {
    thread_local std::vector<float> extended, ahead, behind;
    circularWindowMax(&scratch[std::size_t(x)], &values[std::size_t(x)], width, height, reach,
                      extended, ahead, behind);
  });
}

// Each cell's lowest and highest corner (the bilinear patch lies between them) and the bound on
// its gradient: d/dx of the patch varies linearly between its two x edge differences, d/dy
// likewise. Cells wrap around the map's edges.
struct CellBounds {
  std::vector<float> lowest, highest, slope;
};

CellBounds cellBounds(const Image& heights, int channel, bool heightIsDepth) {
  const int width = heights.width();
  const int height = heights.height();
  const int c = std::clamp(channel, 0, heights.channels() - 1);
  const auto texel = [&](int x, int y) {
    const float value = heights.at(x % width, y % height, c);
    return heightIsDepth ? 1.0f - value : value;
  };
  const std::size_t cells = std::size_t(width) * std::size_t(height);
  const auto index = [width](int x, int y) {
    return std::size_t(y) * std::size_t(width) + std::size_t(x);
  };

  CellBounds bounds{std::vector<float>(cells), std::vector<float>(cells),
                    std::vector<float>(cells)};
  parallelFor(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const float h00 = texel(x, y), h10 = texel(x + 1, y);
      const float h01 = texel(x, y + 1), h11 = texel(x + 1, y + 1);
      bounds.lowest[index(x, y)] = std::min(std::min(h00, h10), std::min(h01, h11));
      bounds.highest[index(x, y)] = std::max(std::max(h00, h10), std::max(h01, h11));
      const float dx = std::max(std::abs(h10 - h00), std::abs(h11 - h01));
      const float dy = std::max(std::abs(h01 - h00), std::abs(h11 - h10));
      bounds.slope[index(x, y)] = std::sqrt(dx * dx + dy * dy);
    }
  });
  return bounds;
}

// The maximum of `values` over each kBlock x kBlock block of cells.
std::vector<float> blockMaxima(const std::vector<float>& values, int width, int height) {
  const int blockWidth = width / kBlock, blockHeight = height / kBlock;
  std::vector<float> maxima(std::size_t(blockWidth) * std::size_t(blockHeight), 0.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float& most =
          maxima[std::size_t(y / kBlock) * std::size_t(blockWidth) + std::size_t(x / kBlock)];
      most = std::max(most, values[std::size_t(y) * std::size_t(width) + std::size_t(x)]);
    }
  }
  return maxima;
}

}  // namespace

ConeMap buildConeMap(const Image& heights, int channel, bool heightIsDepth) {
  ConeMap cones;
  const int width = heights.width();
  const int height = heights.height();
  if (width <= 0 || height <= 0)
    return cones;
  const std::size_t cells = std::size_t(width) * std::size_t(height);
  const auto index = [width](int x, int y) {
    return std::size_t(y) * std::size_t(width) + std::size_t(x);
  };
  CellBounds bounds = cellBounds(heights, channel, heightIsDepth);
  const std::vector<float>& lowest = bounds.lowest;
  std::vector<float>& highest = bounds.highest;
  std::vector<float>& slope = bounds.slope;
  const float top = *std::max_element(highest.begin(), highest.end());

  // The near square: a segment from the cell to any point within kNearReach cells stays in the
  // cells kNearReach around it, where the field rises at most by their steepest gradient times
  // the segment's length.
  std::vector<float> scratch;
  squareMax(slope, scratch, width, height, kNearReach);
  cones.width = width;
  cones.height = height;
  cones.ratios.resize(cells);
  parallelFor(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const float steepest = slope[index(x, y)];
      cones.ratios[index(x, y)] =
          steepest > 0.0f ? std::min(1.0f / steepest, kMaxConeRatio) : kMaxConeRatio;
    }
  });
  slope = {};

  // Shells beyond: the cells whose Chebyshev distance D (in cells) from the cell is in
  // (inner, outer] are at least `inner` texels away (the gap between two cells D apart is at
  // least D - 1 along one axis) and no higher than the highest corner within `outer`, the
  // maximum of `highest` over that square (built up shell by shell: a square maximum of a square
  // maximum is the maximum over the summed reach). Each shell can only narrow cones; the walk
  // outward stops when no cell's cone could be narrowed by anything farther.
  //
  // From kCoarseFrom cells out, the squares are taken over blocks of kBlock x kBlock cells (a
  // square of blocks holding every cell within `outer` of any cell of the block: a few cells
  // more, a small loss at that distance) so that the wide shells cost 1/16 of the narrow ones.
  // Only for maps whose sizes the blocks divide; other maps stay at full resolution.
  const bool blocked = width % kBlock == 0 && height % kBlock == 0;
  const int blockWidth = width / kBlock, blockHeight = height / kBlock;
  std::vector<float> blockHighest;
  if (blocked)
    blockHighest = blockMaxima(highest, width, height);
  std::vector<float>& within = highest;  // the highest corner within `outer` cells
  int inner = kNearReach;
  int reached = 0;        // the reach `within` holds, in cells
  int blocksReached = 0;  // the reach `blockHighest` holds, in blocks
  while (true) {
    const int outer = std::max(inner + 1, int(std::ceil(inner * kShellGrowth)));
    const bool coarse = blocked && outer >= kCoarseFrom;
    if (coarse) {
      // A cell within `outer` of cell x lies in a block within (outer + kBlock - 1) / kBlock of
      // x's block.
      const int blocksOuter = (outer + kBlock - 1) / kBlock;
      squareMax(blockHighest, scratch, blockWidth, blockHeight, blocksOuter - blocksReached);
      blocksReached = blocksOuter;
    } else {
      squareMax(within, scratch, width, height, outer - reached);
      reached = outer;
    }
    std::atomic<bool> more{false};
    parallelFor(height, [&](int y) {
      bool rowMore = false;
      for (int x = 0; x < width; ++x) {
        float& ratio = cones.ratios[index(x, y)];
        const float low = lowest[index(x, y)];
        const float most = coarse ? blockHighest[std::size_t(y / kBlock) * std::size_t(blockWidth) +
                                                 std::size_t(x / kBlock)]
                                  : within[index(x, y)];
        if (most > low)
          ratio = std::min(ratio, float(inner) / (most - low));
        // Anything beyond `outer` is at least `outer` away and no higher than the top.
        rowMore = rowMore || float(outer) < ratio * (top - low);
      }
      if (rowMore)
        more = true;
    });
    inner = outer;
    // Past half the map both ways the square holds every cell: the top bounds the rest.
    if (!more || (2 * outer + 1 >= width && 2 * outer + 1 >= height))
      break;
  }
  parallelFor(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const float low = lowest[index(x, y)];
      if (top > low)
        cones.ratios[index(x, y)] = std::min(cones.ratios[index(x, y)], float(inner) / (top - low));
    }
  });
  return cones;
}

}  // namespace relief::core::inline tracing
