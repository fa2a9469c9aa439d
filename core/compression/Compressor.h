// Compressing maps into GPU formats and decoding them back. A map is prepared for the format's
// layout (colour as RGB(A), a normal's X and Y for the two-channel formats, a height or other
// single value in red), optionally given a full mip chain (MipChain.h), and encoded level by
// level on all cores with progress and cancel. Sizes that are not multiples of the block size
// are padded by repeating the edge texels, which are left out of each edge block's fit.
#pragma once

#include "core/base/Result.h"
#include "core/base/WorkControl.h"
#include "core/compression/TextureFormat.h"
#include "core/image/Image.h"
#include "core/material/MapSlot.h"

#include <cstdint>
#include <string>
#include <vector>

namespace relief::core::inline compression {

struct CompressedLevel {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> data;  // blocks in rows, top row first
};

struct CompressedTexture {
  TextureFormat format = TextureFormat::Bc1;
  bool srgb = false;  // the colour map: sRGB-encoded texels (the formats' sRGB variants)
  MapSlot slot = MapSlot::Color;
  int sourceChannels = 4;  // channels of the map it was made from
  std::vector<CompressedLevel> levels;
  bool zstdInFile = false;  // read from a KTX2 whose levels were Zstandard-supercompressed

  std::uint64_t byteSize() const;
};

// Bytes of one level: whole blocks covering width x height.
std::uint64_t compressedLevelSize(TextureFormat format, int width, int height);

// Fails with "cancelled" when cancelled, or when the format cannot hold the map (a colour map
// in a one-channel format).
// `spreadNormals` is the normal map a roughness map's mips fold in (settings.roughnessFromNormals;
// RoughnessFold.h); it fails without one, or when the two differ in size.
Result<CompressedTexture> compressMap(const Image& map, MapSlot slot,
                                      const CompressionSettings& settings,
                                      const WorkControl& control = {},
                                      const Image* spreadNormals = nullptr);

// Levels 1.. of the chain `map` ships with in `slot` (MipChain.h; for a roughness map with
// `chain.foldNormalSpread` and `spreadNormals`, RoughnessFold.h), as compressMap and the viewport
// build them. Empty without mipmaps.
Result<std::vector<Image>> shippedMipLevels(const Image& map, MapSlot slot,
                                            const MipChainSpec& chain,
                                            const Image* spreadNormals = nullptr);

// The texels of a level as a GPU samples them: RGBA, without swizzles or rebuilt Z.
Result<Image> decodeLevel(const CompressedTexture& texture, int level = 0);
// A level as a map for its slot again: normals as RGB with Z = sqrt(1 - x^2 - y^2) rebuilt
// for the two-channel formats (reference 003, eq. 2.1), single values as one channel, colour
// with the source's channel count.
Result<Image> decodeAsMap(const CompressedTexture& texture, int level = 0);

// Whether the format can hold a map of this slot, and which formats "compare all" tries.
bool formatSuitsSlot(TextureFormat format, MapSlot slot);
std::vector<TextureFormat> formatsForSlot(MapSlot slot);  // without the half-float formats
// What "compare all" and the Compress panel offer for a map: formatsForSlot, and the half-float
// formats too for a linear map of 16 or 32 bits per channel (float heights, HDR colour), whose
// steps and range 8-bit formats cannot keep.
std::vector<TextureFormat> formatsForMap(const Image& map, MapSlot slot);

// The share of values outside 0..1 (float maps such as EXR heights): every GPU format here
// stores 0..1, so they are clamped. 0 when none.
double shareOutsideUnitRange(const Image& map);

// What a half-float format (BC6H) cannot store, counted in a map's values: the encoder makes
// not-a-number 0, infinities and values beyond the largest half (65504) that half, and in the
// unsigned format negatives 0.
struct HalfFloatClamps {
  std::size_t notANumber = 0;
  std::size_t infinite = 0;
  std::size_t beyondHalf = 0;
  std::size_t negative = 0;  // unsigned format only
  std::size_t total() const { return notANumber + infinite + beyondHalf + negative; }
};
HalfFloatClamps countHalfFloatClamps(const Image& map, bool signedFormat);
// "3 values are not numbers and become 0; ..." for a warning; empty when nothing is clamped.
std::string describeHalfFloatClamps(const HalfFloatClamps& clamps, TextureFormat format);

// For files that do not say what map they hold: what a format's layout suggests (a normal for
// the two-channel formats, a height for one channel, colour otherwise).
MapSlot likelySlot(TextureFormat format);
int likelySourceChannels(TextureFormat format);
// An empty texture of `format` with the slot and channel count the layout suggests, for a
// reader to add the file's levels to.
CompressedTexture textureOfUnknownOrigin(TextureFormat format, bool srgb);

}  // namespace relief::core::inline compression
