// The cone map the `cone` technique steps with (cone step mapping: Dummer 2006; Policarpo and
// Oliveira, "Relaxed Cone Stepping for Relief Mapping", GPU Gems 3 ch. 18), made safe for the
// bilinear field the GPU samples (Bán, Valasek et al., "Robust Cone Step Mapping", EGSR 2024)
// and built in O(N^2 log N) by bounding growing shells around every cell at once (after Valasek
// and Bán, "Quick Cone Map Generation on the GPU", Eurographics 2022 short papers).
//
// Cells lie between texel centres, as in MaxMipPyramid.h: cell (i, j) spans texels i..i+1 and
// j..j+1 (wrapping), rows as the image stores them. Distances are in texels, heights in the
// normalised 0..1 of the map (inverted for depth maps). A cell's ratio w is a width per unit
// height with this guarantee, for every point p of the cell and every point q of the repeating
// bilinear field f:
//
//     f(q) - f(p) <= |q - p| / w
//
// so the upward cone of ratio w at (p, f(p)) holds no part of the surface: a ray at height z
// over p that falls dt while moving s dt texels stays above it for dt <= (z - f(p)) w / (s + w).
// Texel-sampled cones (the original algorithms) only exclude the texel centres; the 2024 paper
// shows that a ray can then cross the bilinear surface between two samples. Here the bound
// holds for every point:
// - within the 3x3 cells around the cell, from the field's largest gradient there (a bilinear
//   patch is Lipschitz with the norm of its largest edge differences);
// - beyond, shell by shell: the cells between Chebyshev distances a and b (growing by 1.25x)
//   are at least a texels away and no higher than the highest corner within b, a running
//   maximum of growing reach over the whole map (the 2022 paper bounds rings of maximum-mipmap
//   blocks the same way, at distances that double; its "discarding already visited regions" is
//   the inner radius here).
// The cones are conservative (they never hold the surface), not relaxed: the shader ends its
// walk with the exact bilinear intersection in the cell it reaches, so it needs no overshoot.
#pragma once

#include "core/image/Image.h"

#include <vector>

namespace relief::core::inline tracing {

// A flat map's cones are unbounded; they are stored as this (wider than any ray needs: a ray
// crosses at most the map's size in texels per unit of height at the views the shader allows).
inline constexpr float kMaxConeRatio = 1.0e5f;

struct ConeMap {
  int width = 0;
  int height = 0;
  std::vector<float> ratios;  // row-major, rows as in the image
  float at(int x, int y) const {
    return ratios[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  }
};

// The cone map of `channel` of `heights` (inverted when it holds depths). Multi-threaded; a
// 4096x4096 map takes a few seconds.
ConeMap buildConeMap(const Image& heights, int channel, bool heightIsDepth);

}  // namespace relief::core::inline tracing
