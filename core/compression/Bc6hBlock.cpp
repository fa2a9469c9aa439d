// BC6H blocks; see Bc6hBlock.h.
#include "core/compression/Bc6hBlock.h"

#include "core/compression/Bc7Block.h"

#include <array>
#include <cstdlib>
#include <string_view>

namespace relief::core::inline compression {
namespace {

// Table.F of ARB_texture_compression_bptc, in kBc6hModes' order, as the specification writes
// it: fields from the block's least significant bit up; v[a:b] moves bits into v[b] first,
// towards v[a] (so v[10:15] is stored reversed). The two-subset modes' partition, d[4:0],
// follows at bit 77.
constexpr std::string_view kLayouts[kBc6hModeCount] = {
    "m[1:0],g2[4],b2[4],b3[4],r0[9:0],g0[9:0],b0[9:0],r1[4:0],g3[4],g2[3:0],g1[4:0],b3[0],"
    "g3[3:0],b1[4:0],b3[1],b2[3:0],r2[4:0],b3[2],r3[4:0],b3[3]",
    "m[1:0],g2[5],g3[4],g3[5],r0[6:0],b3[0],b3[1],b2[4],g0[6:0],b2[5],b3[2],g2[4],b0[6:0],b3[3],"
    "b3[5],b3[4],r1[5:0],g2[3:0],g1[5:0],g3[3:0],b1[5:0],b2[3:0],r2[5:0],r3[5:0]",
    "m[4:0],r0[9:0],g0[9:0],b0[9:0],r1[4:0],r0[10],g2[3:0],g1[3:0],g0[10],b3[0],g3[3:0],b1[3:0],"
    "b0[10],b3[1],b2[3:0],r2[4:0],b3[2],r3[4:0],b3[3]",
    "m[4:0],r0[9:0],g0[9:0],b0[9:0],r1[3:0],r0[10],g3[4],g2[3:0],g1[4:0],g0[10],g3[3:0],b1[3:0],"
    "b0[10],b3[1],b2[3:0],r2[3:0],b3[0],b3[2],r3[3:0],g2[4],b3[3]",
    "m[4:0],r0[9:0],g0[9:0],b0[9:0],r1[3:0],r0[10],b2[4],g2[3:0],g1[3:0],g0[10],b3[0],g3[3:0],"
    "b1[4:0],b0[10],b2[3:0],r2[3:0],b3[1],b3[2],r3[3:0],b3[4],b3[3]",
    "m[4:0],r0[8:0],b2[4],g0[8:0],g2[4],b0[8:0],b3[4],r1[4:0],g3[4],g2[3:0],g1[4:0],b3[0],"
    "g3[3:0],b1[4:0],b3[1],b2[3:0],r2[4:0],b3[2],r3[4:0],b3[3]",
    "m[4:0],r0[7:0],g3[4],b2[4],g0[7:0],b3[2],g2[4],b0[7:0],b3[3],b3[4],r1[5:0],g2[3:0],g1[4:0],"
    "b3[0],g3[3:0],b1[4:0],b3[1],b2[3:0],r2[5:0],r3[5:0]",
    "m[4:0],r0[7:0],b3[0],b2[4],g0[7:0],g2[5],g2[4],b0[7:0],g3[5],b3[4],r1[4:0],g3[4],g2[3:0],"
    "g1[5:0],g3[3:0],b1[4:0],b3[1],b2[3:0],r2[4:0],b3[2],r3[4:0],b3[3]",
    "m[4:0],r0[7:0],b3[1],b2[4],g0[7:0],b2[5],g2[4],b0[7:0],b3[5],b3[4],r1[4:0],g3[4],g2[3:0],"
    "g1[4:0],b3[0],g3[3:0],b1[5:0],b2[3:0],r2[4:0],b3[2],r3[4:0],b3[3]",
    "m[4:0],r0[5:0],g3[4],b3[0],b3[1],b2[4],g0[5:0],g2[5],b2[5],b3[2],g2[4],b0[5:0],g3[5],b3[3],"
    "b3[5],b3[4],r1[5:0],g2[3:0],g1[5:0],g3[3:0],b1[5:0],b2[3:0],r2[5:0],r3[5:0]",
    "m[4:0],r0[9:0],g0[9:0],b0[9:0],r1[9:0],g1[9:0],b1[9:0]",
    "m[4:0],r0[9:0],g0[9:0],b0[9:0],r1[8:0],r0[10],g1[8:0],g0[10],b1[8:0],b0[10]",
    "m[4:0],r0[9:0],g0[9:0],b0[9:0],r1[7:0],r0[10:11],g1[7:0],g0[10:11],b1[7:0],b0[10:11]",
    "m[4:0],r0[9:0],g0[9:0],b0[9:0],r1[3:0],r0[10:15],g1[3:0],g0[10:15],b1[3:0],b0[10:15]",
};

// Where one header bit goes: field 0..11 is endpoint (field / 3), channel (field % 3); the mode
// and partition bits are kModeField and kPartitionField.
constexpr int kModeField = 12;
constexpr int kPartitionField = 13;
struct HeaderBit {
  std::uint8_t field;
  std::uint8_t bit;
};
constexpr int kTwoSubsetHeaderBits = 82;  // 77 endpoint and mode bits, then 5 partition bits
constexpr int kOneSubsetHeaderBits = 65;

struct Layout {
  HeaderBit bits[kTwoSubsetHeaderBits];
  int count = 0;
};

int parseNumber(std::string_view text, std::size_t& at) {
  int value = 0;
  while (at < text.size() && text[at] >= '0' && text[at] <= '9')
    value = value * 10 + (text[at++] - '0');
  return value;
}

// One layout string to its bit descriptors (the strings are constants, checked by the tests:
// every mode's descriptors cover exactly its header bits).
Layout parseLayout(std::string_view text, int subsets) {
  Layout layout;
  std::size_t at = 0;
  while (at < text.size()) {
    int field = kModeField;
    if (text[at] != 'm') {
      const char channelLetter = text[at];
      const int endpoint = text[at + 1] - '0';
      const int channel = channelLetter == 'r' ? 0 : channelLetter == 'g' ? 1 : 2;
      field = endpoint * 3 + channel;
      ++at;
    }
    at += 2;  // the letter or digit, then '['
    const int high = parseNumber(text, at);
    int low = high;
    if (text[at] == ':') {
      ++at;
      low = parseNumber(text, at);
    }
    at += 2;  // "]," (or past the end)
    const int step = high >= low ? 1 : -1;
    for (int bit = low;; bit += step) {
      layout.bits[layout.count++] = {std::uint8_t(field), std::uint8_t(bit)};
      if (bit == high)
        break;
    }
  }
  if (subsets == 2) {
    for (int bit = 0; bit < 5; ++bit)
      layout.bits[layout.count++] = {std::uint8_t(kPartitionField), std::uint8_t(bit)};
  }
  return layout;
}

const std::array<Layout, kBc6hModeCount>& layouts() {
  static const std::array<Layout, kBc6hModeCount> parsed = [] {
    std::array<Layout, kBc6hModeCount> all;
    for (int mode = 0; mode < kBc6hModeCount; ++mode)
      all[std::size_t(mode)] = parseLayout(kLayouts[mode], kBc6hModes[mode].subsets);
    return all;
  }();
  return parsed;
}

int headerBits(const Bc6hMode& mode) {
  return mode.subsets == 2 ? kTwoSubsetHeaderBits : kOneSubsetHeaderBits;
}

int bitAt(const std::uint8_t* bytes, int position) {
  return (bytes[position >> 3] >> (position & 7)) & 1;
}

int signExtend(int value, int bits) {
  const int sign = 1 << (bits - 1);
  return (value & (sign - 1)) - (value & sign);
}

bool isAnchorTexel(int subsets, int partition, int texel) {
  return texel == 0 || (subsets == 2 && bc7Anchor(2, partition, 1) == texel);
}

}  // namespace

void packBc6hBlock(const Bc6hBlock& block, std::uint8_t out[16]) {
  const Bc6hMode& mode = kBc6hModes[block.mode];
  const Layout& layout = layouts()[std::size_t(block.mode)];
  for (int i = 0; i < 16; ++i)
    out[i] = 0;
  int position = 0;
  const auto put = [&](int value) {
    out[position >> 3] = std::uint8_t(out[position >> 3] | (value & 1) << (position & 7));
    ++position;
  };
  for (int i = 0; i < layout.count; ++i) {
    const HeaderBit& bit = layout.bits[i];
    const int value = bit.field == kModeField        ? mode.code
                      : bit.field == kPartitionField ? block.partition
                                                     : block.fields[bit.field / 3][bit.field % 3];
    put(value >> bit.bit);
  }
  const int indexBits = mode.subsets == 2 ? 3 : 4;
  for (int texel = 0; texel < 16; ++texel) {
    const int bits = indexBits - (isAnchorTexel(mode.subsets, block.partition, texel) ? 1 : 0);
    for (int i = 0; i < bits; ++i)
      put(block.indices[texel] >> i);
  }
}

bool unpackBc6hBlock(const std::uint8_t in[16], Bc6hBlock& block) {
  const int code = (in[0] & 3) < 2 ? in[0] & 3 : in[0] & 31;
  block = Bc6hBlock{};
  block.mode = -1;
  for (int mode = 0; mode < kBc6hModeCount; ++mode) {
    if (kBc6hModes[mode].code == code)
      block.mode = mode;
  }
  if (block.mode < 0)
    return false;
  const Bc6hMode& mode = kBc6hModes[block.mode];
  const Layout& layout = layouts()[std::size_t(block.mode)];
  for (int i = 0; i < layout.count; ++i) {
    const HeaderBit& bit = layout.bits[i];
    const int value = bitAt(in, i) << bit.bit;
    if (bit.field == kPartitionField)
      block.partition |= value;
    else if (bit.field != kModeField)
      block.fields[bit.field / 3][bit.field % 3] |= value;
  }
  int position = headerBits(mode);
  const int indexBits = mode.subsets == 2 ? 3 : 4;
  for (int texel = 0; texel < 16; ++texel) {
    const int bits = indexBits - (isAnchorTexel(mode.subsets, block.partition, texel) ? 1 : 0);
    int index = 0;
    for (int i = 0; i < bits; ++i)
      index |= bitAt(in, position++) << i;
    block.indices[texel] = std::uint8_t(index);
  }
  return true;
}

void bc6hEndpoints(const Bc6hBlock& block, bool isSigned, int out[4][3]) {
  const Bc6hMode& mode = kBc6hModes[block.mode];
  const int endpoints = mode.subsets * 2;
  const int mask = (1 << mode.endpointBits) - 1;
  for (int channel = 0; channel < 3; ++channel) {
    const int base = block.fields[0][channel];
    out[0][channel] = isSigned ? signExtend(base, mode.endpointBits) : base;
    for (int e = 1; e < endpoints; ++e) {
      int value = block.fields[e][channel];
      if (isSigned || mode.transformed)
        value = signExtend(value, mode.deltaBits[channel]);
      if (mode.transformed) {
        value = (base + value) & mask;
        if (isSigned)
          value = signExtend(value, mode.endpointBits);
      }
      out[e][channel] = value;
    }
  }
}

int bc6hUnquantize(int value, int endpointBits, bool isSigned) {
  if (!isSigned) {
    if (endpointBits >= 15 || value == 0)
      return value;
    if (value == (1 << endpointBits) - 1)
      return 0xFFFF;
    return ((value << 15) + 0x4000) >> (endpointBits - 1);
  }
  if (endpointBits >= 16)
    return value;
  const bool negative = value < 0;
  const int magnitude = std::abs(value);
  int unquantized = 0;
  if (magnitude == 0)
    unquantized = 0;
  else if (magnitude >= (1 << (endpointBits - 1)) - 1)
    unquantized = 0x7FFF;
  else
    unquantized = ((magnitude << 15) + 0x4000) >> (endpointBits - 1);
  return negative ? -unquantized : unquantized;
}

std::uint16_t bc6hFinishUnquantize(int value, bool isSigned) {
  if (!isSigned)
    return std::uint16_t((value * 31) >> 6);
  return value < 0 ? std::uint16_t((((-value) * 31) >> 5) | 0x8000)
                   : std::uint16_t((value * 31) >> 5);
}

void decodeBc6hBlock(const std::uint8_t in[16], bool isSigned, std::uint16_t halves[16][3]) {
  Bc6hBlock block;
  if (!unpackBc6hBlock(in, block)) {
    for (int texel = 0; texel < 16; ++texel)
      halves[texel][0] = halves[texel][1] = halves[texel][2] = 0;
    return;
  }
  const Bc6hMode& mode = kBc6hModes[block.mode];
  int endpoints[4][3];
  bc6hEndpoints(block, isSigned, endpoints);
  int unquantized[4][3];
  for (int e = 0; e < mode.subsets * 2; ++e) {
    for (int channel = 0; channel < 3; ++channel)
      unquantized[e][channel] = bc6hUnquantize(endpoints[e][channel], mode.endpointBits, isSigned);
  }
  const int indexBits = mode.subsets == 2 ? 3 : 4;
  for (int texel = 0; texel < 16; ++texel) {
    const int subset = bc7Subset(mode.subsets, block.partition, texel);
    const int weight = bc7Weight(block.indices[texel], indexBits);
    for (int channel = 0; channel < 3; ++channel) {
      const int value = bc7Interpolate(unquantized[subset * 2][channel],
                                       unquantized[subset * 2 + 1][channel], weight);
      halves[texel][channel] = bc6hFinishUnquantize(value, isSigned);
    }
  }
}

}  // namespace relief::core::inline compression
