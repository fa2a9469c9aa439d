// BC6H (BPTC float) blocks: the mode table, packing and unpacking of the 128-bit block, and
// decoding to half floats. The layout is ARB_texture_compression_bptc's "BPTC float" section
// (the same block as D3D11's BC6H_UF16 / BC6H_SF16 and Vulkan's BC6H_UFLOAT / SFLOAT): a mode
// number in the low 2 or 5 bits, then endpoint bits scattered by a per-mode table (Table.F), the
// partition of two-subset modes, and the indices (each subset's anchor texel one bit shorter, as
// in BC7; BC6H uses the first 32 of BC7's two-subset partitions).
//
// Decoding, per the specification: e0 is sign-extended for the signed format; the other
// endpoints are sign-extended when the format is signed or the mode transforms them, and a
// transformed endpoint is e0 + delta wrapped at the endpoint bits. Endpoints are unquantised to
// 16 bits, interpolated as BC7 interpolates (weights of 64), and the result scaled by 31/64
// (unsigned) or 31/32 (signed, on the magnitude) into half-float bits.
#pragma once

#include <cstdint>

namespace relief::core::inline compression {

// One row of the specification's Table.MF.
struct Bc6hMode {
  int code;          // the mode number stored in the block (0, 1: two bits; otherwise five)
  bool transformed;  // endpoints after e0 are stored as deltas from it
  int subsets;       // 2 with 5 partition bits and 3-bit indices, 1 with 4-bit indices
  int endpointBits;  // EPB
  int deltaBits[3];  // stored bits of the other endpoints per channel (EPB when not transformed)
};

inline constexpr int kBc6hModeCount = 14;
// Two-subset modes first (codes 0, 1, 2, 6, 10, 14, 18, 22, 26, 30), then one-subset (3, 7,
// 11, 15). Codes 19, 23, 27 and 31 are reserved: such a block decodes to black.
inline constexpr Bc6hMode kBc6hModes[kBc6hModeCount] = {
    {0, true, 2, 10, {5, 5, 5}},  {1, true, 2, 7, {6, 6, 6}},      {2, true, 2, 11, {5, 4, 4}},
    {6, true, 2, 11, {4, 5, 4}},  {10, true, 2, 11, {4, 4, 5}},    {14, true, 2, 9, {5, 5, 5}},
    {18, true, 2, 8, {6, 5, 5}},  {22, true, 2, 8, {5, 6, 5}},     {26, true, 2, 8, {5, 5, 6}},
    {30, false, 2, 6, {6, 6, 6}}, {3, false, 1, 10, {10, 10, 10}}, {7, true, 1, 11, {9, 9, 9}},
    {11, true, 1, 12, {8, 8, 8}}, {15, true, 1, 16, {4, 4, 4}}};

// A block's fields as stored: endpoint 0 in endpointBits, the others in deltaBits (deltas for
// transformed modes), each as the unsigned bit pattern of its field.
struct Bc6hBlock {
  int mode = 10;  // index into kBc6hModes
  int partition = 0;
  int fields[4][3] = {};  // [endpoint: subset 0's two, then subset 1's][channel]
  std::uint8_t indices[16] = {};
};

void packBc6hBlock(const Bc6hBlock& block, std::uint8_t out[16]);
// False for a reserved mode.
bool unpackBc6hBlock(const std::uint8_t in[16], Bc6hBlock& block);

// The endpoints as the decoder sees them before unquantisation (sign extension and the
// transform undone): EPB-bit values, negative only for the signed format.
void bc6hEndpoints(const Bc6hBlock& block, bool isSigned, int out[4][3]);
// The specification's unquantisation of an EPB-bit endpoint value to 16 bits.
int bc6hUnquantize(int value, int endpointBits, bool isSigned);
// The last step: an interpolated 16-bit value to half-float bits.
std::uint16_t bc6hFinishUnquantize(int value, bool isSigned);

// Half-float bits (RGB) of the 16 texels, row-major; a reserved mode gives 0.
void decodeBc6hBlock(const std::uint8_t in[16], bool isSigned, std::uint16_t halves[16][3]);

}  // namespace relief::core::inline compression
