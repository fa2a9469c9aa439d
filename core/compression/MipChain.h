// Mipmap chains for maps: each level half the size of the one above (rounded down, at least
// 1), box-filtered by area so odd sizes weigh partial texels correctly. Colour is averaged in
// linear light and re-encoded to sRGB; normals are decoded to vectors, averaged and
// renormalised; heights and other data are averaged as stored.
#pragma once

#include "core/image/Image.h"
#include "core/material/MapSlot.h"

#include <vector>

namespace relief::core::inline compression {

// Level 0 is `image` itself; the last level is 1x1.
std::vector<Image> buildMipChain(const Image& image, MapSlot slot);

// One level down.
Image downsampleForSlot(const Image& image, MapSlot slot);

int mipLevelCount(int width, int height);

}  // namespace relief::core::inline compression
