// Rate-distortion optimisation of block-compressed levels for LZ supercompression (Zstandard in
// KTX2, or a game's own LZ), in the manner of bc7enc_rdo's entropy reduction and Basis
// Universal's RDO: after a level is encoded, each block is replaced, where it pays, by a
// variant that repeats bytes of blocks just before it (to its left in the row, and above it in
// the row before), which an LZ coder stores as a short match instead of literals. A variant is
// taken when it lowers   D + lambda * R,   D the block's squared error against the map (8-bit
// units, summed over its texels and the channels the format stores) and R an estimate of its
// bits after LZ (a whole block repeated: 24 bits; a run of 3 or more bytes repeated at the same
// place in a nearby block: 20 bits; other bytes 8 bits each). Variants are the nearby blocks
// whole and, per format, their parts spliced into this block: BC1's endpoints or selectors,
// BC4's indices, BC3's and BC5's halves and their parts, BC7's halves. Every variant is a valid
// block of the format (any bit pattern after a valid mode is), decoded and measured here.
//
// Smooth blocks guard against banding: a block whose texels span less than 16 levels (of 255)
// weighs its error up to 8 times, so gradients keep their encoder's fit.
#pragma once

#include "core/compression/BlockCodecs.h"
#include "core/compression/TextureFormat.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace relief::core::inline compression {

// The largest lambda the CLI, presets and the panel take: past it every block that can be a
// copy is one.
inline constexpr double kMaxRdoLambda = 1000.0;

// BC1, BC3, BC4, BC5 and BC7: the formats RDO rewrites.
bool formatHasRdo(TextureFormat format);

// The map's texels of block (bx, by) as the encoder saw them, and which lie inside the level.
using BlockSource = std::function<void(int bx, int by, BlockTexels& texels, int& validMask)>;

// Rewrites the blocks of one level (blocksX x blocksY, row-major) in place. lambda <= 0 leaves
// them as they are. Rows are taken in stripes of 32 block rows on all cores; a stripe's first
// row looks only to its left.
void reduceBlockEntropy(TextureFormat format, float lambda, int blocksX, int blocksY,
                        const BlockSource& source, std::vector<std::uint8_t>& blocks);

// The pass's rate estimate for one block against its nearby blocks (exposed for tests).
int estimatedBlockBits(TextureFormat format, const std::uint8_t* block,
                       const std::vector<const std::uint8_t*>& nearby);

}  // namespace relief::core::inline compression
