// BC7 (BPTC) blocks: the mode table, the partition tables, and packing, unpacking and decoding
// of the 128-bit block. The layout is the Khronos Data Format Specification 1.3's "BPTC
// Compressed Texture Image Formats" (the same block as D3D11's BC7 and
// ARB_texture_compression_bptc's RGBA_BPTC_UNORM): a unary mode number in the low bits, then
// partition, rotation and index-selection fields, the endpoints channel by channel (R of every
// endpoint, then G, B, A), the p-bits, and the indices, where each subset's anchor texel stores
// one bit fewer (its top bit is 0).
#pragma once

#include <cstdint>

namespace relief::core::inline compression {

// One row of the specification's "Mode-dependent BPTC parameters" table.
struct Bc7Mode {
  int subsets;
  int partitionBits;
  int rotationBits;
  int indexSelectionBits;
  int colourBits;     // per channel, without the p-bit
  int alphaBits;      // 0: no alpha endpoints (alpha decodes as 255)
  int endpointPBits;  // 1: one p-bit per endpoint, the low bit of all its channels
  int sharedPBits;    // 1: one p-bit per subset, shared by its two endpoints
  int indexBits;
  int secondaryIndexBits;  // modes 4 and 5: the second index set
};

inline constexpr Bc7Mode kBc7Modes[8] = {
    {3, 4, 0, 0, 4, 0, 1, 0, 3, 0}, {2, 6, 0, 0, 6, 0, 0, 1, 3, 0}, {3, 6, 0, 0, 5, 0, 0, 0, 2, 0},
    {2, 6, 0, 0, 7, 0, 1, 0, 2, 0}, {1, 0, 2, 1, 5, 6, 0, 0, 2, 3}, {1, 0, 2, 0, 7, 8, 0, 0, 2, 2},
    {1, 0, 0, 0, 7, 7, 1, 0, 4, 0}, {2, 6, 0, 0, 5, 5, 1, 0, 2, 0}};

// A block's fields, unpacked. Endpoints are the stored (quantised) values without p-bits.
struct Bc7Block {
  int mode = 6;
  int partition = 0;
  int rotation = 0;        // 1, 2, 3: alpha swapped with red, green, blue after decoding
  int indexSelection = 0;  // modes 4: 1 gives colour the 3-bit set and alpha the 2-bit one
  std::uint8_t endpoints[3][2][4] = {};  // [subset][endpoint][channel]
  std::uint8_t pBits[3][2] = {};         // [subset][endpoint]; a shared p-bit is stored in both
  std::uint8_t indices[16] = {};
  std::uint8_t secondaryIndices[16] = {};
};

// The subset (0..subsets-1) of a texel (y * 4 + x) in a partition; one subset: always 0.
int bc7Subset(int subsets, int partition, int texel);
// The anchor texel of a subset: 0 for subset 0, else from the specification's anchor tables.
int bc7Anchor(int subsets, int partition, int subset);
// Whether a texel is the anchor of one of its partition's subsets (its index drops the top bit).
bool bc7IsAnchor(int subsets, int partition, int texel);
// The interpolation weights (of 64) of indices with 2, 3 and 4 bits (BC6H uses the same).
inline constexpr int kBc7Weights2[4] = {0, 21, 43, 64};
inline constexpr int kBc7Weights3[8] = {0, 9, 18, 27, 37, 46, 55, 64};
inline constexpr int kBc7Weights4[16] = {0,  4,  9,  13, 17, 21, 26, 30,
                                         34, 38, 43, 47, 51, 55, 60, 64};
// The interpolation weight (of 64) of an index with 2, 3 or 4 bits.
inline int bc7Weight(int index, int indexBits) {
  return indexBits == 2   ? kBc7Weights2[index]
         : indexBits == 3 ? kBc7Weights3[index]
                          : kBc7Weights4[index];
}
// ((64 - w) e0 + w e1 + 32) >> 6, the specification's interpolation.
inline int bc7Interpolate(int e0, int e1, int weight) {
  return ((64 - weight) * e0 + weight * e1 + 32) >> 6;
}
// The 8-bit value of a `bits`-bit endpoint channel (p-bit included): the top bits repeated.
inline int bc7Expand(int value, int bits) {
  value <<= 8 - bits;
  return value | (value >> bits);
}
// The 8-bit value of one decoded endpoint channel of `block`.
int bc7EndpointValue(const Bc7Block& block, int subset, int endpoint, int channel);

void packBc7Block(const Bc7Block& block, std::uint8_t out[16]);
// False for the reserved mode 8 (the low byte 0), which decodes as transparent black.
bool unpackBc7Block(const std::uint8_t in[16], Bc7Block& block);
// RGBA8 texels in row-major order, as the specification decodes them.
void decodeBc7Block(const std::uint8_t in[16], std::uint8_t rgba[16][4]);

}  // namespace relief::core::inline compression
