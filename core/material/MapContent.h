// What a map's texels say it is, for files whose names say nothing: a tangent-space normal map
// is bluish, its mean near (0.5, 0.5, 1), and its texels decode to unit vectors. The map loader
// uses it so that a normal map is never offered as colour.
#pragma once

#include "core/image/Image.h"

namespace relief::core::inline material {

// True when `image` reads as a tangent-space normal map (OpenGL or DirectX convention): three
// or more channels, mean red and green within 0.08 of 0.5, mean blue at least 0.7, and at least
// 90% of the texels sampled decoding (2c - 1) to a length between 0.8 and 1.2.
bool looksLikeNormalMap(const Image& image);

}  // namespace relief::core::inline material
