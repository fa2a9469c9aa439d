// BlockRdo; see BlockRdo.h.
#include "core/compression/BlockRdo.h"

#include "core/base/ParallelFor.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <span>

namespace relief::core::inline compression {
namespace {

// Bits of the LZ tokens the estimate counts (a match's offset and length, a literal byte).
constexpr int kWholeBlockMatchBits = 24;
constexpr int kPartMatchBits = 20;
constexpr int kLiteralBits = 8;
constexpr int kMinMatchBytes = 3;  // Zstandard's shortest match
// Nearby blocks: this many to the left in the row, and the three above.
constexpr int kLeftBlocks = 8;
constexpr int kStripeRows = 32;
// The smooth-block guard: error weighed by up to kSmoothWeight below kSmoothRange levels.
constexpr float kSmoothWeight = 8.0f;
constexpr float kSmoothRange = 16.0f;

struct Part {
  int begin;
  int end;
};

// The byte ranges of a block that mean something alone (and a repeat of which LZ can store).
std::span<const Part> partsOf(TextureFormat format) {
  static constexpr Part kBc1[] = {{0, 4}, {4, 8}};                     // endpoints | selectors
  static constexpr Part kBc4[] = {{0, 2}, {2, 8}};                     // endpoints | indices
  static constexpr Part kBc3[] = {{0, 2}, {2, 8}, {8, 12}, {12, 16}};  // alpha | colour
  static constexpr Part kBc5[] = {{0, 2}, {2, 8}, {8, 10}, {10, 16}};  // red | green
  static constexpr Part kBc7[] = {{0, 8}, {8, 16}};
  if (format == TextureFormat::Bc1)
    return kBc1;
  if (format == TextureFormat::Bc4)
    return kBc4;
  if (format == TextureFormat::Bc3)
    return kBc3;
  if (format == TextureFormat::Bc5)
    return kBc5;
  return kBc7;  // BC7; formatHasRdo admits no other
}

// Which decoded channels the format stores (others are constants a GPU fills in).
std::array<bool, 4> storedChannels(TextureFormat format) {
  switch (textureFormatInfo(format).layout) {
    case FormatLayout::R:
      return {true, false, false, false};
    case FormatLayout::NormalRg:
      return {true, true, false, false};
    case FormatLayout::Rgb:  // BC1's alpha too: a three-colour block's black is transparent
    case FormatLayout::Rgba:
    case FormatLayout::NormalAg:
    case FormatLayout::RgbHalf:  // never asked: formatHasRdo admits no half-float format
      return {true, true, true, true};
  }
  return {true, true, true, true};  // not reached: every layout is handled above
}

struct BlockJudge {
  TextureFormat format;
  std::array<bool, 4> channels;
  const BlockTexels* source;
  int validMask;

  float error(const std::uint8_t* block) const {
    BlockTexels decoded;
    decodeBcBlock(format, block, decoded);
    float sum = 0.0f;
    for (int t = 0; t < 16; ++t) {
      if (!(validMask & (1 << t)))
        continue;
      for (int c = 0; c < 4; ++c) {
        if (channels[c]) {
          const float d = (decoded[t][c] - (*source)[t][c]) * 255.0f;
          sum += d * d;
        }
      }
    }
    return sum;
  }

  // 1 for a block with detail, up to kSmoothWeight for a flat one.
  float smoothWeight() const {
    float range = 0.0f;
    for (int c = 0; c < 4; ++c) {
      if (!channels[c])
        continue;
      float low = 1.0f, high = 0.0f;
      for (int t = 0; t < 16; ++t) {
        if (validMask & (1 << t)) {
          low = std::min(low, (*source)[t][c]);
          high = std::max(high, (*source)[t][c]);
        }
      }
      range = std::max(range, (high - low) * 255.0f);
    }
    return range >= kSmoothRange ? 1.0f
                                 : kSmoothWeight - (kSmoothWeight - 1.0f) * range / kSmoothRange;
  }
};

}  // namespace

bool formatHasRdo(TextureFormat format) {
  using enum TextureFormat;
  return format == Bc1 || format == Bc3 || format == Bc4 || format == Bc5 || format == Bc7;
}

int estimatedBlockBits(TextureFormat format, const std::uint8_t* block,
                       const std::vector<const std::uint8_t*>& nearby) {
  const int size = textureFormatInfo(format).bytesPerBlock;
  for (const std::uint8_t* other : nearby) {
    if (std::memcmp(block, other, std::size_t(size)) == 0)
      return kWholeBlockMatchBits;
  }
  int bits = 0;
  for (const Part& part : partsOf(format)) {
    const int length = part.end - part.begin;
    bool repeated = false;
    if (length >= kMinMatchBytes) {
      for (const std::uint8_t* other : nearby) {
        if (std::memcmp(block + part.begin, other + part.begin, std::size_t(length)) == 0) {
          repeated = true;
          break;
        }
      }
    }
    bits += repeated ? kPartMatchBits : length * kLiteralBits;
  }
  return bits;
}

void reduceBlockEntropy(TextureFormat format, float lambda, int blocksX, int blocksY,
                        const BlockSource& source, std::vector<std::uint8_t>& blocks) {
  if (lambda <= 0.0f || !formatHasRdo(format))
    return;
  const int size = textureFormatInfo(format).bytesPerBlock;
  const std::span<const Part> parts = partsOf(format);
  const std::array<bool, 4> channels = storedChannels(format);
  const int stripes = (blocksY + kStripeRows - 1) / kStripeRows;
  parallelFor(stripes, [&](int stripe) {
    const int firstRow = stripe * kStripeRows;
    const int endRow = std::min(blocksY, firstRow + kStripeRows);
    BlockTexels texels;
    std::array<std::uint8_t, 16> candidate{}, best{};
    std::vector<const std::uint8_t*> nearby;
    for (int by = firstRow; by < endRow; ++by) {
      for (int bx = 0; bx < blocksX; ++bx) {
        std::uint8_t* block =
            blocks.data() +
            (std::size_t(by) * std::size_t(blocksX) + std::size_t(bx)) * std::size_t(size);
        nearby.clear();
        for (int left = 1; left <= kLeftBlocks && bx - left >= 0; ++left)
          nearby.push_back(block - std::ptrdiff_t(left) * size);
        if (by > firstRow) {
          for (int dx = -1; dx <= 1; ++dx) {
            if (bx + dx >= 0 && bx + dx < blocksX)
              nearby.push_back(block - std::ptrdiff_t(blocksX - dx) * size);
          }
        }
        if (nearby.empty())
          continue;
        int validMask = 0;
        source(bx, by, texels, validMask);
        const BlockJudge judge{format, channels, &texels, validMask};
        const float weight = judge.smoothWeight();
        std::memcpy(best.data(), block, std::size_t(size));
        float bestCost =
            weight * judge.error(block) + lambda * float(estimatedBlockBits(format, block, nearby));
        const auto consider = [&] {
          if (std::memcmp(candidate.data(), block, std::size_t(size)) == 0)
            return;
          const float cost = weight * judge.error(candidate.data()) +
                             lambda * float(estimatedBlockBits(format, candidate.data(), nearby));
          if (cost < bestCost) {
            bestCost = cost;
            best = candidate;
          }
        };
        for (const std::uint8_t* other : nearby) {
          std::memcpy(candidate.data(), other, std::size_t(size));  // the whole block
          consider();
          for (const Part& part : parts) {  // one part of it in this block
            if (part.end - part.begin < kMinMatchBytes)
              continue;
            std::memcpy(candidate.data(), block, std::size_t(size));
            std::memcpy(candidate.data() + part.begin, other + part.begin,
                        std::size_t(part.end - part.begin));
            consider();
          }
        }
        std::memcpy(block, best.data(), std::size_t(size));
      }
    }
  });
}

}  // namespace relief::core::inline compression
