// Bc7Block; see Bc7Block.h. The partition and anchor tables are the specification's (Khronos
// Data Format 1.3, "BPTC": the 2- and 3-subset partition tables and the anchor index tables),
// stored here with two bits per texel. CompressedSamplingTest checks every partition of every
// mode against what the GL driver decodes.
#include "core/compression/Bc7Block.h"

#include <utility>

namespace relief::core::inline compression {
namespace {

// Two subsets: partition -> 2 bits per texel (texel 0 in the low bits).
constexpr std::uint32_t kPartitions2[64] = {
    0x50505050, 0x40404040, 0x54545454, 0x54505040, 0x50404000, 0x55545450, 0x55545040, 0x54504000,
    0x50400000, 0x55555450, 0x55544000, 0x54400000, 0x55555440, 0x55550000, 0x55555500, 0x55000000,
    0x55150100, 0x00004054, 0x15010000, 0x00405054, 0x00004050, 0x15050100, 0x05010000, 0x40505054,
    0x00404050, 0x05010100, 0x14141414, 0x05141450, 0x01155440, 0x00555500, 0x15014054, 0x05414150,
    0x44444444, 0x55005500, 0x11441144, 0x05055050, 0x05500550, 0x11114444, 0x41144114, 0x44111144,
    0x15055054, 0x01055040, 0x05041050, 0x05455150, 0x14414114, 0x50050550, 0x41411414, 0x00141400,
    0x00041504, 0x00105410, 0x10541000, 0x04150400, 0x50410514, 0x41051450, 0x05415014, 0x14054150,
    0x41050514, 0x41505014, 0x40011554, 0x54150140, 0x50505500, 0x00555050, 0x15151010, 0x54540404,
};
// Three subsets.
constexpr std::uint32_t kPartitions3[64] = {
    0xAA685050, 0x6A5A5040, 0x5A5A4200, 0x5450A0A8, 0xA5A50000, 0xA0A05050, 0x5555A0A0, 0x5A5A5050,
    0xAA550000, 0xAA555500, 0xAAAA5500, 0x90909090, 0x94949494, 0xA4A4A4A4, 0xA9A59450, 0x2A0A4250,
    0xA5945040, 0x0A425054, 0xA5A5A500, 0x55A0A0A0, 0xA8A85454, 0x6A6A4040, 0xA4A45000, 0x1A1A0500,
    0x0050A4A4, 0xAAA59090, 0x14696914, 0x69691400, 0xA08585A0, 0xAA821414, 0x50A4A450, 0x6A5A0200,
    0xA9A58000, 0x5090A0A8, 0xA8A09050, 0x24242424, 0x00AA5500, 0x24924924, 0x24499224, 0x50A50A50,
    0x500AA550, 0xAAAA4444, 0x66660000, 0xA5A0A5A0, 0x50A050A0, 0x69286928, 0x44AAAA44, 0x66666600,
    0xAA444444, 0x54A854A8, 0x95809580, 0x96969600, 0xA85454A8, 0x80959580, 0xAA141414, 0x96960000,
    0xAAAA1414, 0xA05050A0, 0xA0A5A5A0, 0x96000000, 0x40804080, 0xA9A8A9A8, 0xAAAAAA44, 0x2A4A5254,
};
// Anchor texel of subset 1 with two subsets.
constexpr std::uint8_t kAnchor2[64] = {
    15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 2,  8, 2,  2, 8,
    8,  15, 2,  8,  2,  2,  8,  8,  2,  2,  15, 15, 6,  8,  2,  8,  15, 15, 2, 8,  2, 2,
    2,  15, 15, 6,  6,  2,  6,  8,  15, 15, 2,  2,  15, 15, 15, 15, 15, 2,  2, 15,
};
// Anchor texels of subsets 1 and 2 with three subsets.
constexpr std::uint8_t kAnchor3[2][64] = {
    {
        3,  3,  15, 15, 8, 3,  15, 15, 8,  8,  6, 6,  6, 5,  3, 3,  3,  3,  8,  15, 3,  3,
        6,  10, 5,  8,  8, 6,  8,  5,  15, 15, 8, 15, 3, 5,  6, 10, 8,  15, 15, 3,  15, 5,
        15, 15, 15, 15, 3, 15, 5,  5,  5,  8,  5, 10, 5, 10, 8, 13, 15, 12, 3,  3,
    },
    {
        15, 8, 8, 3,  15, 15, 3,  8,  15, 15, 15, 15, 15, 15, 15, 8,  15, 8,  15, 3,  15, 8,
        15, 8, 3, 15, 6,  10, 15, 15, 10, 8,  15, 3,  15, 10, 10, 8,  9,  10, 6,  15, 8,  15,
        3,  6, 6, 8,  15, 3,  15, 15, 15, 15, 15, 15, 15, 15, 15, 15, 3,  15, 15, 8,
    }};

// The 128 bits, least significant bit first (bit 0 is bit 0 of byte 0).
class BitWriter {
 public:
  void put(std::uint32_t value, int bits) {
    for (int i = 0; i < bits; ++i, ++m_position) {
      if ((value >> i) & 1)
        m_bytes[m_position >> 3] = std::uint8_t(m_bytes[m_position >> 3] | 1 << (m_position & 7));
    }
  }
  void copyTo(std::uint8_t out[16]) const {
    for (int i = 0; i < 16; ++i)
      out[i] = m_bytes[i];
  }

 private:
  std::uint8_t m_bytes[16] = {};
  int m_position = 0;
};

class BitReader {
 public:
  explicit BitReader(const std::uint8_t in[16]) : m_bytes(in) {}
  int take(int bits) {
    int value = 0;
    for (int i = 0; i < bits; ++i, ++m_position)
      value |= ((m_bytes[m_position >> 3] >> (m_position & 7)) & 1) << i;
    return value;
  }

 private:
  const std::uint8_t* m_bytes;
  int m_position = 0;
};

}  // namespace

bool bc7IsAnchor(int subsets, int partition, int texel) {
  for (int subset = 0; subset < subsets; ++subset) {
    if (bc7Anchor(subsets, partition, subset) == texel)
      return true;
  }
  return false;
}

int bc7Subset(int subsets, int partition, int texel) {
  switch (subsets) {
    case 2:
      return int(kPartitions2[partition] >> (2 * texel)) & 3;
    case 3:
      return int(kPartitions3[partition] >> (2 * texel)) & 3;
    default:
      return 0;
  }
}

int bc7Anchor(int subsets, int partition, int subset) {
  if (subset == 0)
    return 0;
  return subsets == 2 ? kAnchor2[partition] : kAnchor3[subset - 1][partition];
}

int bc7EndpointValue(const Bc7Block& block, int subset, int endpoint, int channel) {
  const Bc7Mode& mode = kBc7Modes[block.mode];
  int bits = channel < 3 ? mode.colourBits : mode.alphaBits;
  if (bits == 0)
    return 255;
  int value = block.endpoints[subset][endpoint][channel];
  if (mode.endpointPBits || mode.sharedPBits) {
    value = value << 1 | block.pBits[subset][endpoint];
    ++bits;
  }
  return bc7Expand(value, bits);
}

void packBc7Block(const Bc7Block& block, std::uint8_t out[16]) {
  const Bc7Mode& mode = kBc7Modes[block.mode];
  BitWriter bits;
  bits.put(1u << block.mode, block.mode + 1);
  bits.put(std::uint32_t(block.partition), mode.partitionBits);
  bits.put(std::uint32_t(block.rotation), mode.rotationBits);
  bits.put(std::uint32_t(block.indexSelection), mode.indexSelectionBits);
  for (int channel = 0; channel < 4; ++channel) {
    const int channelBits = channel < 3 ? mode.colourBits : mode.alphaBits;
    for (int subset = 0; subset < mode.subsets; ++subset) {
      for (int endpoint = 0; endpoint < 2; ++endpoint)
        bits.put(block.endpoints[subset][endpoint][channel], channelBits);
    }
  }
  for (int subset = 0; subset < mode.subsets; ++subset) {
    if (mode.endpointPBits) {
      bits.put(block.pBits[subset][0], 1);
      bits.put(block.pBits[subset][1], 1);
    } else if (mode.sharedPBits) {
      bits.put(block.pBits[subset][0], 1);
    }
  }
  for (int texel = 0; texel < 16; ++texel) {
    const bool anchor = bc7IsAnchor(mode.subsets, block.partition, texel);
    bits.put(block.indices[texel], mode.indexBits - (anchor ? 1 : 0));
  }
  if (mode.secondaryIndexBits) {
    for (int texel = 0; texel < 16; ++texel)
      bits.put(block.secondaryIndices[texel], mode.secondaryIndexBits - (texel == 0 ? 1 : 0));
  }
  bits.copyTo(out);
}

bool unpackBc7Block(const std::uint8_t in[16], Bc7Block& block) {
  if (in[0] == 0)
    return false;
  block = Bc7Block{};
  block.mode = __builtin_ctz(in[0]);
  const Bc7Mode& mode = kBc7Modes[block.mode];
  BitReader bits(in);
  bits.take(block.mode + 1);
  block.partition = bits.take(mode.partitionBits);
  block.rotation = bits.take(mode.rotationBits);
  block.indexSelection = bits.take(mode.indexSelectionBits);
  for (int channel = 0; channel < 4; ++channel) {
    const int channelBits = channel < 3 ? mode.colourBits : mode.alphaBits;
    for (int subset = 0; subset < mode.subsets; ++subset) {
      for (int endpoint = 0; endpoint < 2; ++endpoint)
        block.endpoints[subset][endpoint][channel] = std::uint8_t(bits.take(channelBits));
    }
  }
  for (int subset = 0; subset < mode.subsets; ++subset) {
    if (mode.endpointPBits) {
      block.pBits[subset][0] = std::uint8_t(bits.take(1));
      block.pBits[subset][1] = std::uint8_t(bits.take(1));
    } else if (mode.sharedPBits) {
      block.pBits[subset][0] = block.pBits[subset][1] = std::uint8_t(bits.take(1));
    }
  }
  for (int texel = 0; texel < 16; ++texel) {
    const bool anchor = bc7IsAnchor(mode.subsets, block.partition, texel);
    block.indices[texel] = std::uint8_t(bits.take(mode.indexBits - (anchor ? 1 : 0)));
  }
  if (mode.secondaryIndexBits) {
    for (int texel = 0; texel < 16; ++texel) {
      block.secondaryIndices[texel] =
          std::uint8_t(bits.take(mode.secondaryIndexBits - (texel == 0 ? 1 : 0)));
    }
  }
  return true;
}

void decodeBc7Block(const std::uint8_t in[16], std::uint8_t rgba[16][4]) {
  Bc7Block block;
  if (!unpackBc7Block(in, block)) {
    for (int texel = 0; texel < 16; ++texel)
      rgba[texel][0] = rgba[texel][1] = rgba[texel][2] = rgba[texel][3] = 0;
    return;
  }
  const Bc7Mode& mode = kBc7Modes[block.mode];
  int endpoints[3][2][4];
  for (int subset = 0; subset < mode.subsets; ++subset) {
    for (int endpoint = 0; endpoint < 2; ++endpoint) {
      for (int channel = 0; channel < 4; ++channel)
        endpoints[subset][endpoint][channel] = bc7EndpointValue(block, subset, endpoint, channel);
    }
  }
  // Modes 4 and 5 index colour and alpha separately; index selection swaps the two sets.
  const bool twoSets = mode.secondaryIndexBits > 0;
  const bool swapSets = twoSets && block.indexSelection == 1;
  const int colourBits = swapSets ? mode.secondaryIndexBits : mode.indexBits;
  const int alphaBits = twoSets && !swapSets ? mode.secondaryIndexBits : mode.indexBits;
  for (int texel = 0; texel < 16; ++texel) {
    const int subset = bc7Subset(mode.subsets, block.partition, texel);
    const int primary = block.indices[texel];
    const int secondary = twoSets ? block.secondaryIndices[texel] : primary;
    const int colourWeight = bc7Weight(swapSets ? secondary : primary, colourBits);
    const int alphaWeight = bc7Weight(twoSets && !swapSets ? secondary : primary, alphaBits);
    const int(&e)[2][4] = endpoints[subset];
    int value[4];
    for (int channel = 0; channel < 3; ++channel)
      value[channel] = bc7Interpolate(e[0][channel], e[1][channel], colourWeight);
    value[3] = bc7Interpolate(e[0][3], e[1][3], alphaWeight);
    if (block.rotation > 0)
      std::swap(value[3], value[block.rotation - 1]);
    for (int channel = 0; channel < 4; ++channel)
      rgba[texel][channel] = std::uint8_t(value[channel]);
  }
}

}  // namespace relief::core::inline compression
