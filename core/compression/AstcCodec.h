// ASTC LDR through Arm's astcenc, whole images at a time. Encoding runs in strips of block
// rows, each strip on every core (astcenc threads by thread index on one context), so progress
// is reported and a cancel is honoured between strips; blocks do not depend on each other, so
// the strips give the same bytes as one call.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/compression/TextureFormat.h"
#include "core/image/Image.h"

#include <cstdint>
#include <vector>

namespace relief::core::inline compression {

// `rgba` holds 4 channels in 0..1 (sRGB-encoded values when `srgb`).
Result<std::vector<std::uint8_t>> encodeAstc(TextureFormat format, CompressionQuality quality,
                                             bool srgb, const Image& rgba,
                                             const WorkControl& control = {});
// Returns RGBA (sRGB-encoded values when `srgb`, as the sRGB format stores them).
Result<Image> decodeAstc(TextureFormat format, bool srgb, const std::uint8_t* data,
                         std::size_t size, int width, int height);

}  // namespace relief::core::inline compression
