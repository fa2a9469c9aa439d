// The maximum-mipmap pyramid of a height map (Tevs, Ihrke and Seidel, "Maximum Mipmaps for Fast,
// Accurate, and Scalable Dynamic Height Field Rendering", I3D 2008): a bound on the bilinear
// height field over every cell and every block of cells, so a ray can skip whole blocks it passes
// above and descend only where it may meet the surface (the `quadtree` technique).
//
// Cells lie between texel centres: cell (i, j) spans texels i..i+1 and j..j+1 (wrapping, as the
// field repeats), where the bilinear field never exceeds the largest of its four texels, so
// level 0 holds that maximum. Level k halves level k-1 with floor sizes, as OpenGL's mip chain
// does; the last cell of an odd row or column also takes the dangling child, so cell c of level
// k bounds level-0 cells [c 2^k, (c + 1) 2^k), the last one to the end. Rows are stored as the
// image stores them (top first), as the texture is uploaded.
#pragma once

#include "core/image/Image.h"

#include <vector>

namespace relief::core::inline tracing {

struct MaxMipLevel {
  int width = 0;
  int height = 0;
  std::vector<float> values;  // row-major, rows as in the image
  float at(int x, int y) const {
    return values[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  }
};

struct MaxMipPyramid {
  std::vector<MaxMipLevel> levels;  // levels[0]: one cell per texel; the last is 1x1
};

// Builds the pyramid of `channel` of `heights`, inverted first when it holds depths (the shader
// reads h = 1 - depth). Multi-threaded; a 4096x4096 map takes a few tens of milliseconds.
MaxMipPyramid buildMaxMipPyramid(const Image& heights, int channel, bool heightIsDepth);

}  // namespace relief::core::inline tracing
