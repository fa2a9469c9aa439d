// BC6H encoder (Bc6hBlock.h holds the block layout and the decoder).
//
// BC6H interpolates endpoints as 16-bit integers whose last step (x 31/64, or x 31/32 on the
// magnitude) gives half-float bits, and half-float bits grow roughly with log2 of the value. So
// the encoder works in that integer domain (each texel's half bits x 64/31): a straight line
// there is what the block can represent, and squared error there weighs a texel's error by its
// size in stops, as HDR encoders are judged (multi-exposure PSNR, log error).
//
// Per block: one subset fitted once (principal axis, then least squares on the chosen weights);
// the 32 two-subset partitions ranked by how well two lines fit their halves, and the best few
// fitted. Each fit is tried in the modes of the most endpoint bits whose deltas fit (a finer
// grid of the same shape loses nothing; modes 3 and 30 store endpoints as they are and always
// fit): the endpoints quantised with each subset ordered so its anchor texel needs no flip,
// indices picked against the palette the decoder will build. The least error wins; normal and
// best refit the winner to its own indices and nudge its stored endpoints a step at a time.
//
// Weighing texels by brightness (what multi-exposure PSNR sees) was tried and left out: on the
// bench's eight HDRIs it moved exposure PSNR by 0.1 dB at best and worsened the log error.
#include "core/compression/Bc6hBlock.h"
#include "core/compression/Bc7Block.h"
#include "core/compression/BlockCodecs.h"
#include "core/image/HalfFloat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace relief::core::inline compression {
namespace {

struct Texels {
  float value[16][3];  // the interpolation-domain targets
  int validMask;
  bool isSigned;
};

// What the decoder must produce for a value: its half bits scaled back through the last step.
// Not-a-number becomes 0, infinities the largest half (the specification's advice), negatives
// 0 for the unsigned format.
float interpolationTarget(float value, bool isSigned) {
  if (std::isnan(value))
    value = 0.0f;
  value = std::clamp(value, isSigned ? -kMaxHalf : 0.0f, kMaxHalf);
  const std::uint16_t half = floatToHalf(value);
  if (!isSigned)
    return std::min(65535.0f, float(half) * 64.0f / 31.0f);
  const float magnitude = std::min(32767.0f, float(half & 0x7FFF) * 32.0f / 31.0f);
  return (half & 0x8000) ? -magnitude : magnitude;
}

float domainLow(bool isSigned) {
  return isSigned ? -32767.0f : 0.0f;
}
float domainHigh(bool isSigned) {
  return isSigned ? 32767.0f : 65535.0f;
}

// BC6H's 32 two-subset partitions (BC7's first 32), texel by texel, looked up in the inner
// loops without a call.
const std::array<std::array<std::uint8_t, 16>, 32> kSubsets = [] {
  std::array<std::array<std::uint8_t, 16>, 32> table{};
  for (int partition = 0; partition < 32; ++partition) {
    for (int texel = 0; texel < 16; ++texel)
      table[std::size_t(partition)][std::size_t(texel)] =
          std::uint8_t(bc7Subset(2, partition, texel));
  }
  return table;
}();

int subsetOf(int subsets, int partition, int texel) {
  return subsets == 1 ? 0 : kSubsets[std::size_t(partition)][std::size_t(texel)];
}

// A subset's texels (valid ones only), their mean and covariance (xx, xy, xz, yy, yz, zz).
struct SubsetStatistics {
  int members[16];
  int count = 0;
  float mean[3] = {0, 0, 0};
  float cov[6] = {0, 0, 0, 0, 0, 0};
};

SubsetStatistics subsetStatistics(const Texels& texels, int subsets, int partition, int subset) {
  SubsetStatistics stats;
  for (int texel = 0; texel < 16; ++texel) {
    if ((texels.validMask >> texel & 1) && subsetOf(subsets, partition, texel) == subset)
      stats.members[stats.count++] = texel;
  }
  if (stats.count == 0)
    return stats;
  for (int i = 0; i < stats.count; ++i) {
    for (int c = 0; c < 3; ++c)
      stats.mean[c] += texels.value[stats.members[i]][c];
  }
  for (float& m : stats.mean)
    m /= float(stats.count);
  for (int i = 0; i < stats.count; ++i) {
    const float* v = texels.value[stats.members[i]];
    const float d[3] = {v[0] - stats.mean[0], v[1] - stats.mean[1], v[2] - stats.mean[2]};
    stats.cov[0] += d[0] * d[0];
    stats.cov[1] += d[0] * d[1];
    stats.cov[2] += d[0] * d[2];
    stats.cov[3] += d[1] * d[1];
    stats.cov[4] += d[1] * d[2];
    stats.cov[5] += d[2] * d[2];
  }
  return stats;
}

// The covariance's principal axis by power iteration (from the grey diagonal); returns its
// eigenvalue, 0 when the texels do not spread.
float principalAxis(const float cov[6], int iterations, float axis[3]) {
  axis[0] = axis[1] = axis[2] = 0.57735f;
  float eigen = 0.0f;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const float next[3] = {cov[0] * axis[0] + cov[1] * axis[1] + cov[2] * axis[2],
                           cov[1] * axis[0] + cov[3] * axis[1] + cov[4] * axis[2],
                           cov[2] * axis[0] + cov[4] * axis[1] + cov[5] * axis[2]};
    const float length = std::sqrt(next[0] * next[0] + next[1] * next[1] + next[2] * next[2]);
    if (length <= 1e-12f)
      break;
    eigen = length;
    for (int c = 0; c < 3; ++c)
      axis[c] = next[c] / length;
  }
  return eigen;
}

// The residual of the best line through a subset's texels: total variance minus the largest
// eigenvalue of their covariance. Ranks partitions.
float lineResidual(const Texels& texels, int subsets, int partition, int subset) {
  const SubsetStatistics stats = subsetStatistics(texels, subsets, partition, subset);
  if (stats.count < 2)
    return 0.0f;
  float axis[3];
  const float eigen = principalAxis(stats.cov, 6, axis);
  return std::max(0.0f, stats.cov[0] + stats.cov[3] + stats.cov[5] - eigen);
}

using Endpoints = float[2][3];

// The continuous endpoints of one subset: its principal axis between the extreme projections,
// then `refits` rounds of least squares against the nearest weights.
void fitSubset(const Texels& texels, int subsets, int partition, int subset, int indexBits,
               int refits, Endpoints& out) {
  const SubsetStatistics stats = subsetStatistics(texels, subsets, partition, subset);
  const int count = stats.count;
  const int* members = stats.members;
  const float* mean = stats.mean;
  if (count == 0) {
    for (int c = 0; c < 3; ++c)
      out[0][c] = out[1][c] = 0.0f;
    return;
  }
  float axis[3];
  principalAxis(stats.cov, 8, axis);
  float low = std::numeric_limits<float>::max(), high = -low;
  for (int i = 0; i < count; ++i) {
    const float* v = texels.value[members[i]];
    const float t =
        (v[0] - mean[0]) * axis[0] + (v[1] - mean[1]) * axis[1] + (v[2] - mean[2]) * axis[2];
    low = std::min(low, t);
    high = std::max(high, t);
  }
  for (int c = 0; c < 3; ++c) {
    out[0][c] = mean[c] + low * axis[c];
    out[1][c] = mean[c] + high * axis[c];
  }
  const int entries = 1 << indexBits;
  const float lo = domainLow(texels.isSigned), hi = domainHigh(texels.isSigned);
  for (int round = 0; round < refits; ++round) {
    float a = 0, b = 0, cc = 0, x0[3] = {0, 0, 0}, x1[3] = {0, 0, 0};
    for (int i = 0; i < count; ++i) {
      const float* v = texels.value[members[i]];
      int bestIndex = 0;
      float bestError = std::numeric_limits<float>::max();
      for (int index = 0; index < entries; ++index) {
        const float w = float(bc7Weight(index, indexBits)) / 64.0f;
        float error = 0.0f;
        for (int c = 0; c < 3; ++c) {
          const float d = out[0][c] + (out[1][c] - out[0][c]) * w - v[c];
          error += d * d;
        }
        if (error < bestError) {
          bestError = error;
          bestIndex = index;
        }
      }
      const float w = float(bc7Weight(bestIndex, indexBits)) / 64.0f;
      a += (1 - w) * (1 - w);
      b += (1 - w) * w;
      cc += w * w;
      for (int c = 0; c < 3; ++c) {
        x0[c] += (1 - w) * v[c];
        x1[c] += w * v[c];
      }
    }
    const float det = a * cc - b * b;
    if (std::abs(det) < 1e-6f)
      break;
    for (int c = 0; c < 3; ++c) {
      out[0][c] = std::clamp((cc * x0[c] - b * x1[c]) / det, lo, hi);
      out[1][c] = std::clamp((a * x1[c] - b * x0[c]) / det, lo, hi);
    }
  }
}

// The stored value (endpointBits wide) whose unquantisation lies nearest `target`. Between the
// ends, unquantisation is x s + s / 2 with s = 2^(16 - EPB) (2^(15 - EPB) on the signed
// magnitude), so floor(target / s) is the nearest; the ends (0 stays 0, the top becomes 0xFFFF
// or 0x7FFF) are checked against their neighbours.
int quantize(float target, int bits, bool isSigned) {
  const int top = isSigned ? (1 << (bits - 1)) - 1 : (1 << bits) - 1;
  const float magnitude = isSigned ? std::abs(target) : target;
  const int sign = isSigned && target < 0 ? -1 : 1;
  if (bits == 16)  // stored as it is unquantised
    return sign * std::min(int(std::lround(magnitude)), top);
  const float step = float(1 << (16 - bits));
  const int guess = std::clamp(int(magnitude / step), 0, top);
  if (guess > 1 && guess < top - 1)
    return sign * guess;
  int best = 0;
  float bestError = std::numeric_limits<float>::max();
  for (int m = std::max(0, guess - 1); m <= std::min(top, guess + 1); ++m) {
    const float error = std::abs(float(bc6hUnquantize(sign * m, bits, isSigned)) - target);
    if (error < bestError) {
      bestError = error;
      best = sign * m;
    }
  }
  return best;
}

struct Bc6hCandidate {
  Bc6hBlock block;
  int q[4][3] = {};  // the endpoints as stored values (before deltas)
  float error = std::numeric_limits<float>::max();
};

// Indices against the palette the decoder builds from stored endpoints `q`; anchors limited to
// the low half when `anchorsFixed`. Returns the squared error.
float chooseIndices(const Texels& texels, const Bc6hMode& mode, int partition, const int q[4][3],
                    bool anchorsFixed, std::uint8_t indices[16]) {
  const int indexBits = mode.subsets == 2 ? 3 : 4;
  const int entries = 1 << indexBits;
  float palette[2][16][3];
  for (int subset = 0; subset < mode.subsets; ++subset) {
    int u0[3], u1[3];
    for (int c = 0; c < 3; ++c) {
      u0[c] = bc6hUnquantize(q[subset * 2][c], mode.endpointBits, texels.isSigned);
      u1[c] = bc6hUnquantize(q[subset * 2 + 1][c], mode.endpointBits, texels.isSigned);
    }
    for (int index = 0; index < entries; ++index) {
      const int w = bc7Weight(index, indexBits);
      for (int c = 0; c < 3; ++c)
        palette[subset][index][c] = float(bc7Interpolate(u0[c], u1[c], w));
    }
  }
  float total = 0.0f;
  for (int texel = 0; texel < 16; ++texel) {
    const int subset = subsetOf(mode.subsets, partition, texel);
    const int limit =
        anchorsFixed && bc7IsAnchor(mode.subsets, partition, texel) ? entries / 2 : entries;
    int bestIndex = 0;
    float bestError = std::numeric_limits<float>::max();
    for (int index = 0; index < limit; ++index) {
      float error = 0.0f;
      for (int c = 0; c < 3; ++c) {
        const float d = palette[subset][index][c] - texels.value[texel][c];
        error += d * d;
      }
      if (error < bestError) {
        bestError = error;
        bestIndex = index;
      }
    }
    indices[texel] = std::uint8_t(bestIndex);
    if (texels.validMask >> texel & 1)
      total += bestError;
  }
  return total;
}

// Whether every delta of a transformed mode fits its stored bits (always, untransformed).
bool deltasFit(const Bc6hMode& mode, const int q[4][3]) {
  if (!mode.transformed)
    return true;
  for (int e = 1; e < mode.subsets * 2; ++e) {
    for (int c = 0; c < 3; ++c) {
      const int limit = 1 << (mode.deltaBits[c] - 1);
      const int delta = q[e][c] - q[0][c];
      if (delta < -limit || delta >= limit)
        return false;
    }
  }
  return true;
}

// The stored range of a mode's endpoints: unsigned 0..2^EPB - 1, signed +-(2^(EPB-1) - 1).
std::pair<int, int> storedRange(const Bc6hMode& mode, bool isSigned) {
  if (!isSigned)
    return {0, (1 << mode.endpointBits) - 1};
  const int top = (1 << (mode.endpointBits - 1)) - 1;
  return {-top, top};
}

// The block's fields from stored endpoints: deltas for transformed modes.
void writeFields(const Bc6hMode& mode, const int q[4][3], Bc6hBlock& block) {
  const int mask = (1 << mode.endpointBits) - 1;
  for (int c = 0; c < 3; ++c) {
    block.fields[0][c] = q[0][c] & mask;
    for (int e = 1; e < mode.subsets * 2; ++e) {
      block.fields[e][c] =
          mode.transformed ? (q[e][c] - q[0][c]) & ((1 << mode.deltaBits[c]) - 1) : q[e][c] & mask;
    }
  }
}

// Indices and error for stored endpoints `candidate.q` (whose deltas fit): a subset whose anchor
// index needs its top bit is flipped (endpoints swapped, indices mirrored: the palette mirrors
// exactly, the interpolation being symmetric) when the flipped deltas still fit, otherwise its
// anchor keeps to the low half.
void evaluate(const Texels& texels, Bc6hCandidate& candidate) {
  const Bc6hMode& mode = kBc6hModes[candidate.block.mode];
  const int partition = candidate.block.partition;
  std::uint8_t* indices = candidate.block.indices;
  candidate.error = chooseIndices(texels, mode, partition, candidate.q, false, indices);
  const int top = (1 << (mode.subsets == 2 ? 3 : 4)) - 1;
  bool restricted = false;
  for (int subset = 0; subset < mode.subsets; ++subset) {
    const int anchor = subset == 0 ? 0 : bc7Anchor(2, partition, 1);
    if (indices[anchor] <= top / 2)
      continue;
    int flipped[4][3];
    std::copy(&candidate.q[0][0], &candidate.q[0][0] + 12, &flipped[0][0]);
    for (int c = 0; c < 3; ++c)
      std::swap(flipped[subset * 2][c], flipped[subset * 2 + 1][c]);
    if (!deltasFit(mode, flipped)) {
      restricted = true;
      continue;
    }
    std::copy(&flipped[0][0], &flipped[0][0] + 12, &candidate.q[0][0]);
    for (int texel = 0; texel < 16; ++texel) {
      if (subsetOf(mode.subsets, partition, texel) == subset)
        indices[texel] = std::uint8_t(top - indices[texel]);
    }
  }
  if (restricted)
    candidate.error = chooseIndices(texels, mode, partition, candidate.q, true, indices);
}

// Continuous endpoints `ends` (subset 0's pair, then subset 1's) stored in a mode: quantised,
// each subset first ordered so that its anchor texel lies nearer its first endpoint (its index
// then needs no top bit). False when the mode cannot store the deltas.
bool quantizeForMode(const Texels& texels, int modeIndex, int partition, const Endpoints* ends,
                     Bc6hCandidate& candidate) {
  const Bc6hMode& mode = kBc6hModes[modeIndex];
  candidate.block.mode = modeIndex;
  candidate.block.partition = partition;
  for (int subset = 0; subset < mode.subsets; ++subset) {
    const float* anchor = texels.value[subset == 0 ? 0 : bc7Anchor(2, partition, 1)];
    float toFirst = 0.0f, toSecond = 0.0f;
    for (int c = 0; c < 3; ++c) {
      toFirst += (anchor[c] - ends[subset][0][c]) * (anchor[c] - ends[subset][0][c]);
      toSecond += (anchor[c] - ends[subset][1][c]) * (anchor[c] - ends[subset][1][c]);
    }
    const int first = toSecond < toFirst ? 1 : 0;
    for (int c = 0; c < 3; ++c) {
      candidate.q[subset * 2][c] =
          quantize(ends[subset][first][c], mode.endpointBits, texels.isSigned);
      candidate.q[subset * 2 + 1][c] =
          quantize(ends[subset][1 - first][c], mode.endpointBits, texels.isSigned);
    }
  }
  return deltasFit(mode, candidate.q);
}

// The modes worth trying for endpoints `ends`: those of the most endpoint bits whose deltas fit
// (a finer grid of the same shape loses nothing), evaluated; the best is kept in `best`. The
// untransformed modes (3: ten bits, one subset; 30: six bits, two) always fit.
void tryModes(const Texels& texels, int subsets, int partition, const Endpoints* ends,
              Bc6hCandidate& best) {
  const int first = subsets == 2 ? 0 : 10, last = subsets == 2 ? 10 : kBc6hModeCount;
  int finest = 0;
  Bc6hCandidate fitting[10];
  int count = 0;
  for (int mode = first; mode < last; ++mode) {
    Bc6hCandidate candidate;
    if (!quantizeForMode(texels, mode, partition, ends, candidate))
      continue;
    const int bits = kBc6hModes[mode].endpointBits;
    if (bits < finest)
      continue;
    if (bits > finest) {
      finest = bits;
      count = 0;
    }
    fitting[count++] = candidate;
  }
  for (int i = 0; i < count; ++i) {
    evaluate(texels, fitting[i]);
    if (fitting[i].error < best.error)
      best = fitting[i];
  }
}

// Least squares endpoints for a block's own indices (its subsets and weights), continuous.
void refitToIndices(const Texels& texels, const Bc6hCandidate& candidate, Endpoints* ends) {
  const Bc6hBlock& block = candidate.block;
  const Bc6hMode& mode = kBc6hModes[block.mode];
  const int indexBits = mode.subsets == 2 ? 3 : 4;
  const float lo = domainLow(texels.isSigned), hi = domainHigh(texels.isSigned);
  for (int subset = 0; subset < mode.subsets; ++subset) {
    for (int c = 0; c < 3; ++c) {
      for (int e = 0; e < 2; ++e) {
        ends[subset][e][c] = float(
            bc6hUnquantize(candidate.q[subset * 2 + e][c], mode.endpointBits, texels.isSigned));
      }
    }
    float a = 0, b = 0, cc = 0, x0[3] = {0, 0, 0}, x1[3] = {0, 0, 0};
    for (int texel = 0; texel < 16; ++texel) {
      if (!(texels.validMask >> texel & 1) ||
          subsetOf(mode.subsets, block.partition, texel) != subset)
        continue;
      const float w = float(bc7Weight(block.indices[texel], indexBits)) / 64.0f;
      a += (1 - w) * (1 - w);
      b += (1 - w) * w;
      cc += w * w;
      for (int c = 0; c < 3; ++c) {
        x0[c] += (1 - w) * texels.value[texel][c];
        x1[c] += w * texels.value[texel][c];
      }
    }
    const float det = a * cc - b * b;
    if (std::abs(det) < 1e-6f)
      continue;
    for (int c = 0; c < 3; ++c) {
      ends[subset][0][c] = std::clamp((cc * x0[c] - b * x1[c]) / det, lo, hi);
      ends[subset][1][c] = std::clamp((a * x1[c] - b * x0[c]) / det, lo, hi);
    }
  }
}

// Nudges each stored endpoint channel of the winner a step up or down, keeping a step that
// lowers the error (the quantised optimum is seldom the rounded continuous one). `rounds`
// sweeps over the channels.
void refineStoredEndpoints(const Texels& texels, int rounds, Bc6hCandidate& best) {
  const Bc6hMode& mode = kBc6hModes[best.block.mode];
  const auto [low, high] = storedRange(mode, texels.isSigned);
  for (int round = 0; round < rounds; ++round) {
    bool improved = false;
    for (int e = 0; e < mode.subsets * 2; ++e) {
      for (int c = 0; c < 3; ++c) {
        for (int step : {-1, 1}) {
          Bc6hCandidate trial = best;
          trial.q[e][c] = std::clamp(trial.q[e][c] + step, low, high);
          if (trial.q[e][c] == best.q[e][c] || !deltasFit(mode, trial.q))
            continue;
          evaluate(texels, trial);
          if (trial.error < best.error) {
            best = trial;
            improved = true;
          }
        }
      }
    }
    if (!improved)
      break;
  }
}

struct Bc6hEffort {
  int partitions;    // two-subset partitions fitted, best ranked first
  int refits;        // least-squares rounds of each continuous fit
  int refineRounds;  // sweeps of refineStoredEndpoints over the winner
};

Bc6hEffort effortFor(CompressionQuality quality) {
  switch (quality) {
    case CompressionQuality::Fast:
      return {2, 1, 0};
    case CompressionQuality::Normal:
      return {6, 2, 2};
    case CompressionQuality::Best:
      return {32, 3, 6};
  }
  return {6, 2, 2};  // not reached: every quality is handled above
}

}  // namespace

void encodeBc6hBlock(bool isSigned, CompressionQuality quality, const BlockTexels& input,
                     int validMask, std::uint8_t* out) {
  Texels texels;
  texels.isSigned = isSigned;
  texels.validMask = validMask ? validMask : 0xFFFF;
  for (int texel = 0; texel < 16; ++texel) {
    for (int c = 0; c < 3; ++c)
      texels.value[texel][c] = interpolationTarget(input[texel][c], isSigned);
  }
  const Bc6hEffort effort = effortFor(quality);
  Bc6hCandidate best;

  // One subset: modes 3, 7, 11, 15.
  Endpoints whole[1];
  fitSubset(texels, 1, 0, 0, 4, effort.refits, whole[0]);
  tryModes(texels, 1, 0, whole, best);

  // Two subsets: the best-ranked partitions.
  std::array<std::pair<float, int>, 32> ranked;
  for (int partition = 0; partition < 32; ++partition) {
    ranked[std::size_t(partition)] = {
        lineResidual(texels, 2, partition, 0) + lineResidual(texels, 2, partition, 1), partition};
  }
  std::sort(ranked.begin(), ranked.end());
  for (int i = 0; i < effort.partitions && best.error > 0.0f; ++i) {
    const int partition = ranked[std::size_t(i)].second;
    Endpoints halves[2];
    fitSubset(texels, 2, partition, 0, 3, effort.refits, halves[0]);
    fitSubset(texels, 2, partition, 1, 3, effort.refits, halves[1]);
    tryModes(texels, 2, partition, halves, best);
  }

  // The winner refitted to its own indices (in whichever of its subsets' modes fits best), then
  // its stored endpoints nudged.
  if (effort.refineRounds > 0 && best.error > 0.0f) {
    Endpoints ends[2] = {};
    refitToIndices(texels, best, ends);
    const int subsets = kBc6hModes[best.block.mode].subsets;
    tryModes(texels, subsets, best.block.partition, ends, best);
    refineStoredEndpoints(texels, effort.refineRounds, best);
  }
  writeFields(kBc6hModes[best.block.mode], best.q, best.block);
  packBc6hBlock(best.block, out);
}

}  // namespace relief::core::inline compression
