// Block codecs: one 4x4 block at a time for the BC and ETC/EAC families. Texels are RGBA
// floats in 0..1, row-major (index y * 4 + x); `validMask` bit (y * 4 + x) marks texels inside
// the image (edge blocks of sizes that are not multiples of 4 leave the rest out of the fit).
// Decoders write what a GPU samples from the block, in the same layout.
#pragma once

#include "core/compression/TextureFormat.h"

#include <cstdint>

namespace relief::core::inline compression {

using BlockTexels = float[16][4];

// BC1-BC3 and DXT5nm: encoded with libsquish (range fit, cluster fit, iterative cluster fit
// for fast, normal, best). BC4 and BC5: our own encoder (libsquish's misses the 1 s target for
// 4096^2 BC5; see BcCodec.cpp). All decoded by our own decoder (libsquish decodes BC4/BC5
// wrongly, PLATFORM.md).
// `perceptual` weighs colour error by luminance (colour maps); data maps weigh channels alike.
void encodeBcBlock(TextureFormat format, CompressionQuality quality, bool perceptual,
                   const BlockTexels& texels, int validMask, std::uint8_t* out);
void decodeBcBlock(TextureFormat format, const std::uint8_t* in, BlockTexels& texels);

// ETC1 (android-libetc1; also a valid ETC2 RGB block), ETC2 RGBA (ETC1 colour with our EAC
// alpha), EAC R11 and RG11 (our encoder). Decoding covers every ETC2 mode (individual,
// differential, T, H, planar), so files from other encoders decode too.
void encodeEtcBlock(TextureFormat format, CompressionQuality quality, const BlockTexels& texels,
                    int validMask, std::uint8_t* out);
void decodeEtcBlock(TextureFormat format, const std::uint8_t* in, BlockTexels& texels);

// The pieces, for tests: one EAC block of one channel (11-bit R11 form or 8-bit alpha form).
void encodeEacChannel(const float values[16], int validMask, bool elevenBit,
                      CompressionQuality quality, std::uint8_t out[8]);
void decodeEacChannel(const std::uint8_t in[8], bool elevenBit, float values[16]);
void decodeEtc2Rgb(const std::uint8_t in[8], float rgb[16][3]);

}  // namespace relief::core::inline compression
