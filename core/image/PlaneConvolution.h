// One float plane convolved with a 1D kernel along its rows or its columns, edges clamped: the
// separable filters the metrics apply (SSIM's Gaussian window, FLIP's contrast sensitivity and
// feature filters). Written here rather than with OpenImageIO's ImageBufAlgo::convolve, which
// applies the full 2D kernel and would load OpenImageIO into commands that never read a file
// through it (docs/architecture.md, "Start-up").
#pragma once

#include <vector>

namespace relief::core::inline image {

// `plane` (width x height floats, row-major) convolved with `kernel` (odd length, centred)
// along rows (`alongRows`) or columns into `out` (same size, not `plane`), multi-threaded.
// Texels beyond an edge repeat the edge texel.
void convolvePlane(const float* plane, float* out, int width, int height,
                   const std::vector<float>& kernel, bool alongRows);

}  // namespace relief::core::inline image
