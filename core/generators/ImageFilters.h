// Image filters the generators share: edge handling, a separable Gaussian blur, luminance and
// resizing for previews.
#pragma once

#include "core/base/WorkControl.h"
#include "core/image/Image.h"

#include <vector>

namespace relief::core::inline generators {

enum class EdgeMode { Wrap, Clamp };

// Index i of a line of `size` texels, wrapped around or clamped to the edge.
inline int edgeIndex(int i, int size, EdgeMode edge) {
  if (edge == EdgeMode::Wrap)
    return ((i % size) + size) % size;
  return i < 0 ? 0 : (i >= size ? size - 1 : i);
}

// Every index from -margin to size - 1 + margin, resolved once per line so inner loops need no
// modulo: table[i + margin] is the texel for offset i.
std::vector<int> edgeIndexTable(int size, int margin, EdgeMode edge);

// Gaussian blur of every channel with standard deviation `sigma` texels (truncated at 3
// sigma), separable and multi-threaded. Written here rather than with OpenImageIO's
// ImageBufAlgo::convolve because that one applies the full 2D kernel (too slow for the
// radii used, at 4K and 8K) and has no wrap-around edge for tileable maps.
Image gaussianBlur(const Image& image, double sigma, EdgeMode edge,
                   const WorkControl& control = {});

// Rec. 709 luminance of linear RGB (sRGB images are decoded first); grey images pass through.
Image luminance(const Image& image);

// Resized with a separable Lanczos-3 filter, widened by the scale when shrinking (so every source
// texel contributes: no aliasing), clamped at the edges, multi-threaded. The same filter as
// OpenImageIO's ImageBufAlgo::resize uses when shrinking, written here so that generating and
// exporting maps never load OpenImageIO (its 260 shared libraries take longer than the resize:
// docs/architecture.md, "Start-up").
Image resizeImage(const Image& image, int width, int height);

}  // namespace relief::core::inline generators
