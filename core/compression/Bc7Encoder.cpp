// The BC7 encoder (BlockCodecs.h). Its design follows the published fast encoders (Rich
// Geldreich's bc7enc and Intel's ispc_texcomp): rank the 64 partitions of the 2- and 3-subset
// modes by an estimate, fit only the best few; fit each subset's endpoints on its principal
// axis, quantise them with the p-bit that suits each endpoint, choose indices, then refine the
// endpoints by least squares over those indices. Quality levels differ in how many modes and
// partitions they fit and how hard they refine (kEfforts below).
//
// Error is the sum of squared 8-bit differences over R, G, B and A alike, the quantity PSNR
// measures. Modes without alpha (0 to 3) are charged for the alpha they cannot store, so they
// lose to the alpha modes exactly when the block's alpha matters.
#include "core/base/CpuDispatch.h"
#include "core/compression/Bc7Block.h"
#include "core/compression/BlockCodecs.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

namespace relief::core::inline compression {
namespace {

using Texels8 = int[16][4];

// How hard one quality level tries.
struct Effort {
  bool tryModes[8];
  int partitions2;  // best-ranked 2-subset partitions fitted per mode
  int partitions3;
  int refinePasses;   // least-squares passes after the principal-axis fit
  bool allPBits;      // evaluate every p-bit combination instead of choosing per endpoint
  bool perturb;       // polish the winner: move each stored endpoint channel a step while it helps
  int rotations;      // modes 4 and 5 on translucent blocks: rotations tried (1: "none" only)
  bool opaqueExtras;  // opaque blocks too: modes 4, 5 (every rotation) and 7
};

// Fast: bc7enc's default pair (modes 1 and 6) plus the alpha modes 5 and 7. Normal adds the
// 3-subset modes 0 and 2 and more partitions; best adds mode 3, rotations and polishing.
// Measured on five photographs (tools/bench-compress, mean PSNR and time on two cores): fast
// 43.40 dB in 0.34 s, normal 43.90 dB in 1.1 s, best 44.27 dB in 6 s. Mode 3 added 0.06 dB to
// normal for 25% more time, 16 instead of 8 partitions 0.02 dB to best for 70% more, and
// perturbing every candidate rather than the winner 0.05 dB for 150% more.
constexpr Effort kEfforts[3] = {
    {{false, true, false, false, false, true, true, true}, 1, 0, 1, false, false, 1, false},
    {{true, true, true, false, true, true, true, true}, 4, 2, 2, false, false, 4, false},
    {{true, true, true, true, true, true, true, true}, 8, 4, 3, true, true, 4, true},
};

// Quantisation of an 8-bit value to `bits` stored bits, with p-bit 0 or 1 appended or none
// (index 2): the stored value and what it decodes to, nearest first. Built once.
struct QuantisedValue {
  std::uint8_t stored;
  std::uint8_t decoded;
};
struct QuantisationTables {
  QuantisedValue table[9][3][256];  // [bits][p-bit 0, 1, none][value]
  QuantisationTables() {
    for (int bits = 1; bits <= 8; ++bits) {
      for (int p = 0; p < 3; ++p) {
        const bool hasP = p < 2;
        if (hasP && bits > 7)
          continue;
        for (int value = 0; value < 256; ++value) {
          int best = 0, bestError = 1 << 30;
          for (int stored = 0; stored < (1 << bits); ++stored) {
            const int decoded =
                hasP ? bc7Expand(stored << 1 | p, bits + 1) : bc7Expand(stored, bits);
            if (std::abs(decoded - value) < bestError) {
              bestError = std::abs(decoded - value);
              best = stored;
            }
          }
          const int decoded = hasP ? bc7Expand(best << 1 | p, bits + 1) : bc7Expand(best, bits);
          table[bits][p][value] = {std::uint8_t(best), std::uint8_t(decoded)};
        }
      }
    }
  }
};
const QuantisationTables& quantisation() {
  static const QuantisationTables tables;
  return tables;
}

// For each weight 0..64, the index of the nearest weight with 2, 3 or 4 index bits.
struct NearestIndexTables {
  std::uint8_t table[5][65];
  NearestIndexTables() {
    for (int bits = 2; bits <= 4; ++bits) {
      for (int w = 0; w <= 64; ++w) {
        int best = 0;
        for (int i = 1; i < (1 << bits); ++i) {
          if (std::abs(bc7Weight(i, bits) - w) < std::abs(bc7Weight(best, bits) - w))
            best = i;
        }
        table[bits][w] = std::uint8_t(best);
      }
    }
  }
};
const NearestIndexTables& nearestIndex() {
  static const NearestIndexTables tables;
  return tables;
}

enum class PBits { None, PerEndpoint, Shared };

// What one subset fit works on: a list of texels, the channels fitted together (all with the
// same stored bits), and how endpoints and indices are stored.
struct FitTarget {
  const Texels8* texels;
  const std::uint8_t* list;  // texel positions of the subset
  int count;
  std::uint16_t validMask;  // texels inside the image; others get indices but no weight
  int firstChannel;
  int channels;
  int bits;
  PBits pBits;
  int indexBits;
  // Opaque blocks in modes 6 and 7: alpha 255 needs both p-bits 1 (254 is visible to alpha
  // tests and blending, so it is not traded for colour precision).
  bool pBitsOne = false;
};

struct FitResult {
  int stored[2][4] = {};
  int pBit[2] = {};
  int error = std::numeric_limits<int>::max();
  std::uint8_t indices[16] = {};  // by texel position
};

bool isValid(const FitTarget& target, int texel) {
  return (target.validMask >> texel) & 1;
}

// Indices for the decoded endpoints and the error they leave; one per texel goes to `indices`.
int assignIndices(const FitTarget& target, const int decoded[2][4], std::uint8_t indices[16]) {
  const int levels = 1 << target.indexBits;
  const int first = target.firstChannel, n = target.channels;
  int palette[16][4];
  for (int i = 0; i < levels; ++i) {
    const int w = bc7Weight(i, target.indexBits);
    for (int c = first; c < first + n; ++c)
      palette[i][c] = bc7Interpolate(decoded[0][c], decoded[1][c], w);
  }
  int direction[4] = {}, lengthSquared = 0;
  for (int c = first; c < first + n; ++c) {
    direction[c] = decoded[1][c] - decoded[0][c];
    lengthSquared += direction[c] * direction[c];
  }
  const std::uint8_t* nearest = nearestIndex().table[target.indexBits];
  int total = 0;
  for (int k = 0; k < target.count; ++k) {
    const int texel = target.list[k];
    const int* px = (*target.texels)[texel];
    // The nearest weight on the segment by projection, then its neighbours by true error (the
    // palette's rounding and the distance off the segment can make a neighbour nearer).
    int guess = 0;
    if (lengthSquared > 0) {
      int dot = 0;
      for (int c = first; c < first + n; ++c)
        dot += (px[c] - decoded[0][c]) * direction[c];
      const int w = std::clamp((dot * 64 + lengthSquared / 2) / lengthSquared, 0, 64);
      guess = nearest[dot <= 0 ? 0 : w];
    }
    int best = guess, bestError = std::numeric_limits<int>::max();
    for (int i = std::max(guess - 1, 0); i <= std::min(guess + 1, levels - 1); ++i) {
      int error = 0;
      for (int c = first; c < first + n; ++c) {
        const int d = px[c] - palette[i][c];
        error += d * d;
      }
      if (error < bestError) {
        bestError = error;
        best = i;
      }
    }
    indices[texel] = std::uint8_t(best);
    if (isValid(target, texel))
      total += bestError;
  }
  return total;
}

int decodedValue(const FitTarget& target, int stored, int pBit) {
  if (target.pBits == PBits::None)
    return bc7Expand(stored, target.bits);
  return bc7Expand(stored << 1 | pBit, target.bits + 1);
}

// Evaluates stored endpoints: decodes them, assigns indices, and keeps them in `best` when they
// beat it.
void evaluate(const FitTarget& target, const int stored[2][4], const int pBit[2], FitResult& best) {
  int decoded[2][4] = {};
  for (int e = 0; e < 2; ++e) {
    for (int c = target.firstChannel; c < target.firstChannel + target.channels; ++c)
      decoded[e][c] = decodedValue(target, stored[e][c], pBit[e]);
  }
  std::uint8_t indices[16];
  const int error = assignIndices(target, decoded, indices);
  if (error < best.error) {
    best.error = error;
    std::memcpy(best.stored, stored, sizeof best.stored);
    best.pBit[0] = pBit[0];
    best.pBit[1] = pBit[1];
    for (int k = 0; k < target.count; ++k)
      best.indices[target.list[k]] = indices[target.list[k]];
  }
}

// Quantises one endpoint with p-bit `p` (ignored without p-bits); returns the squared error of
// the decoded endpoint against `value`.
int quantiseEndpoint(const FitTarget& target, const float value[4], int p, int stored[4]) {
  const int column = target.pBits == PBits::None ? 2 : p;
  int error = 0;
  for (int c = target.firstChannel; c < target.firstChannel + target.channels; ++c) {
    // std::lround for the 0..255 the fits clamp to, without its library call (lroundf took 2.6%
    // of the encoder's time).
    const int whole = int(value[c]);
    const int v = std::clamp(whole + (value[c] - float(whole) >= 0.5f ? 1 : 0), 0, 255);
    const QuantisedValue q = quantisation().table[target.bits][column][v];
    stored[c] = q.stored;
    const float d = float(q.decoded) - value[c];
    error += int(d * d);
  }
  return error;
}

// Quantises both endpoints and evaluates them: with p-bits, each endpoint's (or the shared)
// p-bit that quantises best, or every combination when `allPBits`.
void quantiseAndEvaluate(const FitTarget& target, const float endpoints[2][4], bool allPBits,
                         FitResult& best) {
  int stored[2][4] = {};
  int pBit[2] = {0, 0};
  if (target.pBits == PBits::None) {
    quantiseEndpoint(target, endpoints[0], 0, stored[0]);
    quantiseEndpoint(target, endpoints[1], 0, stored[1]);
    evaluate(target, stored, pBit, best);
    return;
  }
  int storedByP[2][2][4] = {};  // [endpoint][p]
  int errorByP[2][2];
  for (int e = 0; e < 2; ++e) {
    for (int p = 0; p < 2; ++p)
      errorByP[e][p] = quantiseEndpoint(target, endpoints[e], p, storedByP[e][p]);
  }
  const auto tryPBits = [&](int p0, int p1) {
    std::memcpy(stored[0], storedByP[0][p0], sizeof stored[0]);
    std::memcpy(stored[1], storedByP[1][p1], sizeof stored[1]);
    const int pair[2] = {p0, p1};
    evaluate(target, stored, pair, best);
  };
  if (target.pBitsOne) {
    tryPBits(1, 1);
  } else if (target.pBits == PBits::Shared) {
    if (allPBits) {
      tryPBits(0, 0);
      tryPBits(1, 1);
    } else {
      const int p = errorByP[0][1] + errorByP[1][1] < errorByP[0][0] + errorByP[1][0] ? 1 : 0;
      tryPBits(p, p);
    }
  } else if (allPBits) {
    for (int p0 = 0; p0 < 2; ++p0) {
      for (int p1 = 0; p1 < 2; ++p1)
        tryPBits(p0, p1);
    }
  } else {
    tryPBits(errorByP[0][1] < errorByP[0][0] ? 1 : 0, errorByP[1][1] < errorByP[1][0] ? 1 : 0);
  }
}

// The principal axis of the subset's texels (power iteration on the covariance) and the two
// ends of their projections on it.
void principalAxisEndpoints(const FitTarget& target, float endpoints[2][4]) {
  const int first = target.firstChannel, n = target.channels;
  float mean[4] = {};
  int weight = 0;
  for (int k = 0; k < target.count; ++k) {
    if (!isValid(target, target.list[k]))
      continue;
    ++weight;
    for (int c = first; c < first + n; ++c)
      mean[c] += float((*target.texels)[target.list[k]][c]);
  }
  if (weight == 0) {
    for (int e = 0; e < 2; ++e) {
      for (int c = first; c < first + n; ++c)
        endpoints[e][c] = float((*target.texels)[target.list[0]][c]);
    }
    return;
  }
  for (int c = first; c < first + n; ++c)
    mean[c] /= float(weight);
  float covariance[4][4] = {};
  for (int k = 0; k < target.count; ++k) {
    if (!isValid(target, target.list[k]))
      continue;
    const int* px = (*target.texels)[target.list[k]];
    for (int i = first; i < first + n; ++i) {
      for (int j = i; j < first + n; ++j)
        covariance[i][j] += (float(px[i]) - mean[i]) * (float(px[j]) - mean[j]);
    }
  }
  for (int i = first; i < first + n; ++i) {
    for (int j = first; j < i; ++j)
      covariance[i][j] = covariance[j][i];
  }
  // Start from the row of the largest variance: it is never orthogonal to the axis.
  int start = first;
  for (int c = first; c < first + n; ++c) {
    if (covariance[c][c] > covariance[start][start])
      start = c;
  }
  float axis[4] = {};
  for (int c = first; c < first + n; ++c)
    axis[c] = covariance[start][c];
  for (int iteration = 0; iteration < 4; ++iteration) {
    float next[4] = {}, length = 0.0f;
    for (int i = first; i < first + n; ++i) {
      for (int j = first; j < first + n; ++j)
        next[i] += covariance[i][j] * axis[j];
      length = std::max(length, std::abs(next[i]));
    }
    if (length <= 0.0f)
      break;
    for (int c = first; c < first + n; ++c)
      axis[c] = next[c] / length;
  }
  float length = 0.0f;
  for (int c = first; c < first + n; ++c)
    length += axis[c] * axis[c];
  float low = 0.0f, high = 0.0f;
  if (length > 0.0f) {
    length = std::sqrt(length);
    for (int c = first; c < first + n; ++c)
      axis[c] /= length;
    low = std::numeric_limits<float>::max();
    high = -low;
    for (int k = 0; k < target.count; ++k) {
      if (!isValid(target, target.list[k]))
        continue;
      const int* px = (*target.texels)[target.list[k]];
      float t = 0.0f;
      for (int c = first; c < first + n; ++c)
        t += (float(px[c]) - mean[c]) * axis[c];
      low = std::min(low, t);
      high = std::max(high, t);
    }
  }
  for (int c = first; c < first + n; ++c) {
    endpoints[0][c] = std::clamp(mean[c] + low * axis[c], 0.0f, 255.0f);
    endpoints[1][c] = std::clamp(mean[c] + high * axis[c], 0.0f, 255.0f);
  }
}

// Least squares for the endpoints given the indices of `fit`: texel = (1 - w) e0 + w e1 for
// each texel's weight w. False when every texel has the same weight (no unique solution).
bool leastSquaresEndpoints(const FitTarget& target, const FitResult& fit, float endpoints[2][4]) {
  float aa = 0, ab = 0, bb = 0;
  float ax[4] = {}, bx[4] = {};
  const int first = target.firstChannel, n = target.channels;
  for (int k = 0; k < target.count; ++k) {
    const int texel = target.list[k];
    if (!isValid(target, texel))
      continue;
    const float w = float(bc7Weight(fit.indices[texel], target.indexBits)) / 64.0f;
    const float v = 1.0f - w;
    aa += v * v;
    ab += v * w;
    bb += w * w;
    for (int c = first; c < first + n; ++c) {
      ax[c] += v * float((*target.texels)[texel][c]);
      bx[c] += w * float((*target.texels)[texel][c]);
    }
  }
  const float determinant = aa * bb - ab * ab;
  if (std::abs(determinant) < 1e-6f)
    return false;
  for (int c = first; c < first + n; ++c) {
    endpoints[0][c] = std::clamp((bb * ax[c] - ab * bx[c]) / determinant, 0.0f, 255.0f);
    endpoints[1][c] = std::clamp((aa * bx[c] - ab * ax[c]) / determinant, 0.0f, 255.0f);
  }
  return true;
}

// Moves each stored endpoint channel one step up or down while the error falls.
void perturb(const FitTarget& target, FitResult& fit) {
  const int maxStored = (1 << target.bits) - 1;
  for (int sweep = 0; sweep < 2; ++sweep) {
    const int before = fit.error;
    for (int e = 0; e < 2; ++e) {
      for (int c = target.firstChannel; c < target.firstChannel + target.channels; ++c) {
        for (int step : {-1, 1}) {
          int stored[2][4];
          std::memcpy(stored, fit.stored, sizeof stored);
          stored[e][c] += step;
          if (stored[e][c] < 0 || stored[e][c] > maxStored)
            continue;
          const int pBit[2] = {fit.pBit[0], fit.pBit[1]};
          evaluate(target, stored, pBit, fit);
        }
      }
    }
    if (fit.error >= before || fit.error == 0)
      break;
  }
}

FitResult fitSubset(const FitTarget& target, const Effort& effort) {
  FitResult best;
  float endpoints[2][4] = {};
  principalAxisEndpoints(target, endpoints);
  quantiseAndEvaluate(target, endpoints, effort.allPBits, best);
  for (int pass = 0; pass < effort.refinePasses && best.error > 0; ++pass) {
    const int before = best.error;
    if (!leastSquaresEndpoints(target, best, endpoints))
      break;
    quantiseAndEvaluate(target, endpoints, effort.allPBits, best);
    if (best.error >= before)
      break;
  }
  if (effort.perturb && best.error > 0)
    perturb(target, best);
  return best;
}

// The block being encoded: texels as 0..255 integers and what every mode needs from them.
struct SourceBlock {
  Texels8 texels;
  std::uint16_t validMask;
  int alphaPenalty;  // what storing alpha as 255 costs (modes 0 to 3)
  bool opaque;
};

// Writes a subset's fit into the block; `indices` receives the subset's texels' indices.
void storeFit(const FitTarget& target, const FitResult& fit, int subset, Bc7Block& block,
              std::uint8_t indices[16]) {
  for (int e = 0; e < 2; ++e) {
    for (int c = target.firstChannel; c < target.firstChannel + target.channels; ++c)
      block.endpoints[subset][e][c] = std::uint8_t(fit.stored[e][c]);
    block.pBits[subset][e] = std::uint8_t(fit.pBit[e]);
  }
  for (int k = 0; k < target.count; ++k)
    indices[target.list[k]] = fit.indices[target.list[k]];
}

// The texels of each subset of a partition.
struct SubsetLists {
  std::uint8_t list[3][16];
  int count[3] = {};
};
SubsetLists subsetLists(int subsets, int partition) {
  SubsetLists lists;
  for (int texel = 0; texel < 16; ++texel) {
    const int subset = bc7Subset(subsets, partition, texel);
    lists.list[subset][lists.count[subset]++] = std::uint8_t(texel);
  }
  return lists;
}

// Flat blocks (every texel the same colour) in mode 5, the solid-colour path fast encoders
// have: per colour channel the pair of 7-bit endpoints whose interpolation at weight 21/64
// (index 1) comes nearest the value, found once for all 256 values (every value is exact), and
// the 8-bit alpha stored as it is.
struct FlatColourTable {
  std::uint8_t endpoints[256][2];
  int error[256];
  FlatColourTable() {
    for (int value = 0; value < 256; ++value) {
      error[value] = 1 << 30;
      for (int q0 = 0; q0 < 128 && error[value] > 0; ++q0) {
        for (int q1 = 0; q1 < 128; ++q1) {
          const int d = bc7Interpolate(bc7Expand(q0, 7), bc7Expand(q1, 7), 21) - value;
          if (d * d < error[value]) {
            error[value] = d * d;
            endpoints[value][0] = std::uint8_t(q0);
            endpoints[value][1] = std::uint8_t(q1);
          }
        }
      }
    }
  }
};
const FlatColourTable& flatColours() {
  static const FlatColourTable table;
  return table;
}

int encodeFlat(const int colour[4], int validTexels, Bc7Block& block) {
  block = Bc7Block{};
  block.mode = 5;
  int error = 0;
  for (int c = 0; c < 3; ++c) {
    block.endpoints[0][0][c] = flatColours().endpoints[colour[c]][0];
    block.endpoints[0][1][c] = flatColours().endpoints[colour[c]][1];
    error += flatColours().error[colour[c]] * validTexels;
  }
  block.endpoints[0][0][3] = block.endpoints[0][1][3] = std::uint8_t(colour[3]);
  std::fill(block.indices, block.indices + 16, std::uint8_t(1));
  return error;
}

// Modes 0, 1, 2, 3, 6 and 7: one index set for all channels.
int encodeOneIndexSet(const SourceBlock& source, int modeNumber, int partition,
                      const Effort& effort, Bc7Block& block) {
  const Bc7Mode& mode = kBc7Modes[modeNumber];
  block = Bc7Block{};
  block.mode = modeNumber;
  block.partition = partition;
  const SubsetLists lists = subsetLists(mode.subsets, partition);
  const PBits pBits = mode.endpointPBits ? PBits::PerEndpoint
                      : mode.sharedPBits ? PBits::Shared
                                         : PBits::None;
  int error = mode.alphaBits ? 0 : source.alphaPenalty;
  for (int subset = 0; subset < mode.subsets; ++subset) {
    FitTarget target{&source.texels,
                     lists.list[subset],
                     lists.count[subset],
                     source.validMask,
                     0,
                     mode.alphaBits ? 4 : 3,
                     mode.colourBits,
                     pBits,
                     mode.indexBits};
    target.pBitsOne = source.opaque && mode.alphaBits > 0 && pBits == PBits::PerEndpoint;
    const FitResult fit = fitSubset(target, effort);
    error += fit.error;
    storeFit(target, fit, subset, block, block.indices);
  }
  return error;
}

// Modes 4 and 5: colour and one scalar channel (alpha, or after a rotation red, green or blue,
// with alpha in its place) fitted separately, each with its own index set.
int encodeTwoIndexSets(const SourceBlock& source, int modeNumber, int rotation, int indexSelection,
                       const Effort& effort, Bc7Block& block) {
  const Bc7Mode& mode = kBc7Modes[modeNumber];
  block = Bc7Block{};
  block.mode = modeNumber;
  block.rotation = rotation;
  block.indexSelection = indexSelection;
  Texels8 rotated;
  std::memcpy(rotated, source.texels, sizeof rotated);
  if (rotation > 0) {
    for (auto& texel : rotated)
      std::swap(texel[3], texel[rotation - 1]);
  }
  const SubsetLists lists = subsetLists(1, 0);
  const int colourIndexBits = indexSelection ? mode.secondaryIndexBits : mode.indexBits;
  const int scalarIndexBits = indexSelection ? mode.indexBits : mode.secondaryIndexBits;
  const FitTarget colour{&rotated, lists.list[0],   16,          source.validMask, 0,
                         3,        mode.colourBits, PBits::None, colourIndexBits};
  const FitTarget scalar{&rotated, lists.list[0],  16,          source.validMask, 3,
                         1,        mode.alphaBits, PBits::None, scalarIndexBits};
  const FitResult colourFit = fitSubset(colour, effort);
  const FitResult scalarFit = fitSubset(scalar, effort);
  storeFit(colour, colourFit, 0, block, indexSelection ? block.secondaryIndices : block.indices);
  storeFit(scalar, scalarFit, 0, block, indexSelection ? block.indices : block.secondaryIndices);
  return colourFit.error + scalarFit.error;
}

// The anchor texel of each subset must have an index below half (its top bit is not stored):
// where it does not, the subset's endpoints trade places and its indices are mirrored.
void fixAnchors(Bc7Block& block) {
  const Bc7Mode& mode = kBc7Modes[block.mode];
  if (mode.secondaryIndexBits) {
    // Index set 1 drives colour (or alpha, with index selection 1), set 2 the other.
    const bool swapSets = block.indexSelection == 1;
    const auto fix = [&](std::uint8_t* indices, int bits, int firstChannel, int channels) {
      if (indices[0] < (1 << (bits - 1)))
        return;
      for (int t = 0; t < 16; ++t)
        indices[t] = std::uint8_t((1 << bits) - 1 - indices[t]);
      for (int c = firstChannel; c < firstChannel + channels; ++c)
        std::swap(block.endpoints[0][0][c], block.endpoints[0][1][c]);
    };
    fix(block.indices, mode.indexBits, swapSets ? 3 : 0, swapSets ? 1 : 3);
    fix(block.secondaryIndices, mode.secondaryIndexBits, swapSets ? 0 : 3, swapSets ? 3 : 1);
    return;
  }
  const int levels = 1 << mode.indexBits;
  for (int subset = 0; subset < mode.subsets; ++subset) {
    const int anchor = bc7Anchor(mode.subsets, block.partition, subset);
    if (block.indices[anchor] < levels / 2)
      continue;
    for (int t = 0; t < 16; ++t) {
      if (bc7Subset(mode.subsets, block.partition, t) == subset)
        block.indices[t] = std::uint8_t(levels - 1 - block.indices[t]);
    }
    for (int c = 0; c < 4; ++c)
      std::swap(block.endpoints[subset][0][c], block.endpoints[subset][1][c]);
    std::swap(block.pBits[subset][0], block.pBits[subset][1]);
  }
}

// Partition ranking without fitting: for each subset, the squared distance of its texels from
// their best line (the scatter matrix's trace less its largest eigenvalue lambda) plus the error
// of spacing `levels` values evenly along that line (a uniform spread of variance lambda leaves
// lambda / (levels - 1)^2). Opaque blocks rank on RGB (alpha has no variance), which saves the
// fourth row of every product.
//
// Computed a partition at a time, this ranking was half of normal quality's time. It now runs
// on several partitions at once, each in a lane of one variable (GCC's and Clang's vector
// extension): every operation acts on each lane with scalar float semantics, so the ranking,
// and the blocks, are the bytes the partition-at-a-time loop gave. Four lanes (an SSE register)
// on the x86-64 baseline, eight where the CPU has AVX2 (rankPartitions below picks). Measured on
// a 2048^2 mosaic of photographs and game colour maps, one thread, normal quality: 6.50 s a
// partition at a time, 4.74 s in four lanes, 4.30 s in eight, the same 45.75 dB (the same
// bytes). Auto-vectorisation of the loop over partitions failed (GCC 12: "control flow in
// loop"), hence the explicit lanes.
typedef float Lanes4 __attribute__((vector_size(16)));
typedef float Lanes8 __attribute__((vector_size(32)));

template <typename V>
constexpr int kLanesOf = int(sizeof(V) / sizeof(float));

template <typename V, int N>
struct PartitionMoments {
  static constexpr int kValues = 1 + N + N * (N + 1) / 2;  // count, sums, products (i <= j)
  V value[kValues][64 / kLanesOf<V>];                      // [value][partition / lanes]
};

// The trace and the largest eigenvalue of each partition's scatter matrix for one subset (two
// power iterations from its largest-variance row, then the Rayleigh quotient: enough to rank
// partitions), added to `offLine` and `alongLine`. Subsets of fewer than two texels add 0.
template <typename V, int N>
[[gnu::always_inline]] inline void addLineResiduals(const PartitionMoments<V, N>& m, V* offLine,
                                                    V* alongLine) {
  const V zero = {};
  for (int g = 0; g < 64 / kLanesOf<V>; ++g) {
    const V n = m.value[0][g];
    V scatter[N][N];
    V trace = zero;
    for (int i = 0, k = 1 + N; i < N; ++i) {
      for (int j = i; j < N; ++j, ++k)
        scatter[i][j] = scatter[j][i] = m.value[k][g] - m.value[1 + i][g] * m.value[1 + j][g] / n;
      trace += scatter[i][i];
    }
    // The row of the largest variance (the first of equals).
    V axis[N], largest = scatter[0][0];
    for (int c = 0; c < N; ++c)
      axis[c] = scatter[0][c];
    for (int r = 1; r < N; ++r) {
      const auto larger = scatter[r][r] > largest;
      largest = larger ? scatter[r][r] : largest;
      for (int c = 0; c < N; ++c)
        axis[c] = larger ? scatter[r][c] : axis[c];
    }
    for (int iteration = 0; iteration < 2; ++iteration) {
      V next[N];
      for (int i = 0; i < N; ++i) {
        next[i] = zero;
        for (int j = 0; j < N; ++j)
          next[i] += scatter[i][j] * axis[j];
      }
      for (int c = 0; c < N; ++c)
        axis[c] = next[c];
    }
    V length = zero, quotient = zero;
    for (int i = 0; i < N; ++i) {
      V row = zero;
      for (int j = 0; j < N; ++j)
        row += scatter[i][j] * axis[j];
      quotient += axis[i] * row;
      length += axis[i] * axis[i];
    }
    // std::clamp(quotient / length, 0, trace), lane by lane.
    V lambda = quotient / length;
    lambda = lambda < zero ? zero : lambda;
    lambda = trace < lambda ? trace : lambda;
    const auto fits = (n >= 2.0f) & (length > zero);
    offLine[g] += fits ? trace - lambda : zero;
    alongLine[g] += fits ? lambda : zero;
  }
}

struct PartitionRanking {
  // Per partition, summed over subsets.
  float offLine[64];
  float alongLine[64];
  // The first `partitions` partitions (mode 0 reaches only 16) ordered by the estimate for an
  // index count; `count` of them are sorted.
  void best(int partitions, int levels, int count, int order[64]) const {
    float score[64];
    const float spacing = 1.0f / float((levels - 1) * (levels - 1));
    for (int p = 0; p < partitions; ++p) {
      score[p] = offLine[p] + alongLine[p] * spacing;
      order[p] = p;
    }
    std::partial_sort(order, order + count, order + partitions,
                      [&](int a, int b) { return score[a] < score[b]; });
  }
};

// For each partition, whether each texel is in subset 1 or 2 (1 or 0), partition-minor as the
// moments are, built once.
struct SubsetWeights {
  float weight[2][2][16][64] = {};  // [subsets - 2][subset - 1][texel][partition]
  SubsetWeights() {
    for (int subsets = 2; subsets <= 3; ++subsets) {
      for (int p = 0; p < 64; ++p) {
        for (int t = 0; t < 16; ++t) {
          const int s = bc7Subset(subsets, p, t);
          if (s > 0)
            weight[subsets - 2][s - 1][t][p] = 1.0f;
        }
      }
    }
  }
};
const SubsetWeights& subsetWeights() {
  static const SubsetWeights weights;
  return weights;
}

template <typename V, int N>
[[gnu::always_inline]] inline PartitionRanking rankPartitionsOf(const SourceBlock& source,
                                                                int subsets) {
  constexpr int kValues = PartitionMoments<V, N>::kValues;
  constexpr int kLanes = kLanesOf<V>, kGroups = 64 / kLanes;
  // Each texel's moments (zero outside the image) and the block's.
  float texel[kValues][16] = {}, block[kValues] = {};
  for (int t = 0; t < 16; ++t) {
    if (!((source.validMask >> t) & 1))
      continue;
    const int* px = source.texels[t];
    texel[0][t] = 1.0f;
    for (int i = 0, k = 1 + N; i < N; ++i) {
      texel[1 + i][t] = float(px[i]);
      for (int j = i; j < N; ++j, ++k)
        texel[k][t] = float(px[i] * px[j]);
    }
  }
  for (int v = 0; v < kValues; ++v) {
    for (int t = 0; t < 16; ++t)
      block[v] += texel[v][t];
  }
  // Subsets 1 and 2 summed from their texels (a texel outside adds an exact 0), subset 0 the
  // block less them.
  PartitionMoments<V, N> subset[3];
  const V zero = {};
  for (int v = 0; v < kValues; ++v) {
    for (int g = 0; g < kGroups; ++g)
      subset[0].value[v][g] = zero + block[v];
  }
  for (int s = 1; s < subsets; ++s) {
    const auto& weight = subsetWeights().weight[subsets - 2][s - 1];
    for (int v = 0; v < kValues; ++v) {
      V* sum = subset[s].value[v];
      for (int g = 0; g < kGroups; ++g)
        sum[g] = zero;
      for (int t = 0; t < 16; ++t) {
        for (int g = 0; g < kGroups; ++g) {
          V w;
          std::memcpy(&w, &weight[t][g * kLanes], sizeof w);
          sum[g] += w * texel[v][t];
        }
      }
      for (int g = 0; g < kGroups; ++g)
        subset[0].value[v][g] -= sum[g];
    }
  }
  V offLine[kGroups] = {}, alongLine[kGroups] = {};
  for (int s = 0; s < subsets; ++s)
    addLineResiduals(subset[s], offLine, alongLine);
  PartitionRanking ranking;
  std::memcpy(ranking.offLine, offLine, sizeof ranking.offLine);
  std::memcpy(ranking.alongLine, alongLine, sizeof ranking.alongLine);
  return ranking;
}

#if RELIEF_HAS_AVX2_DISPATCH
[[gnu::target("avx2")]] PartitionRanking rankPartitionsAvx2(const SourceBlock& source,
                                                            int subsets) {
  return source.opaque ? rankPartitionsOf<Lanes8, 3>(source, subsets)
                       : rankPartitionsOf<Lanes8, 4>(source, subsets);
}
#endif

PartitionRanking rankPartitions(const SourceBlock& source, int subsets) {
#if RELIEF_HAS_AVX2_DISPATCH
  if (cpuHasAvx2())
    return rankPartitionsAvx2(source, subsets);
#endif
  return source.opaque ? rankPartitionsOf<Lanes4, 3>(source, subsets)
                       : rankPartitionsOf<Lanes4, 4>(source, subsets);
}

}  // namespace

void encodeBc7Block(CompressionQuality quality, const BlockTexels& texels, int validMask,
                    std::uint8_t* out) {
  const Effort& effort = kEfforts[int(quality)];
  SourceBlock source;
  source.validMask = std::uint16_t(validMask == 0 ? 0xFFFF : validMask);
  source.alphaPenalty = 0;
  for (int t = 0; t < 16; ++t) {
    for (int c = 0; c < 4; ++c)
      source.texels[t][c] = int(std::lround(std::clamp(texels[t][c], 0.0f, 1.0f) * 255.0f));
    if ((source.validMask >> t) & 1) {
      const int d = 255 - source.texels[t][3];
      source.alphaPenalty += d * d;
    }
  }
  source.opaque = source.alphaPenalty == 0;

  // Perturbation is costly and only needed once: the search runs without it, the winner gets it.
  Effort search = effort;
  search.perturb = false;
  Bc7Block best, candidate;
  int bestError = std::numeric_limits<int>::max();
  const auto consider = [&](int error) {
    if (error < bestError) {
      bestError = error;
      best = candidate;
    }
  };
  int first = 0;
  while (!((source.validMask >> first) & 1))
    ++first;
  bool flat = true;
  for (int t = 0; t < 16 && flat; ++t) {
    if ((source.validMask >> t) & 1)
      flat = std::equal(source.texels[t], source.texels[t] + 4, source.texels[first]);
  }
  if (flat)
    consider(encodeFlat(source.texels[first], std::popcount(source.validMask), candidate));
  // Mode 6 first: one subset, 4-bit indices, alpha; good everywhere and often exact.
  consider(encodeOneIndexSet(source, 6, 0, search, candidate));
  // The alpha modes with two index sets; on opaque blocks only when searching everything.
  for (int mode : {5, 4}) {
    if (bestError == 0 || !effort.tryModes[mode] || (source.opaque && !effort.opaqueExtras))
      continue;
    for (int rotation = 0; rotation < effort.rotations; ++rotation) {
      for (int selection = 0; selection < (mode == 4 ? 2 : 1); ++selection)
        consider(encodeTwoIndexSets(source, mode, rotation, selection, search, candidate));
    }
  }
  // Partitioned modes: the best-ranked partitions of each. Modes 0 to 3 store no alpha, so
  // they are tried only where alpha is 255 (elsewhere their alpha penalty rules them out).
  PartitionRanking rankings[2];
  bool ranked[2] = {false, false};
  for (int mode : {1, 7, 3, 0, 2}) {
    const Bc7Mode& info = kBc7Modes[mode];
    const int partitions = 1 << info.partitionBits;
    const int count =
        std::min(info.subsets == 2 ? effort.partitions2 : effort.partitions3, partitions);
    if (bestError == 0 || !effort.tryModes[mode] || count == 0)
      continue;
    if (info.alphaBits == 0 && !source.opaque)
      continue;
    if (mode == 7 && source.opaque && !effort.opaqueExtras)
      continue;  // mode 7 spends bits on alpha an opaque block does not need
    const int r = info.subsets - 2;
    if (!ranked[r]) {
      rankings[r] = rankPartitions(source, info.subsets);
      ranked[r] = true;
    }
    int order[64];
    rankings[r].best(partitions, 1 << info.indexBits, count, order);
    for (int k = 0; k < count && bestError > 0; ++k)
      consider(encodeOneIndexSet(source, mode, order[k], search, candidate));
  }
  if (effort.perturb && bestError > 0) {
    const Bc7Block winner = best;
    if (kBc7Modes[winner.mode].secondaryIndexBits) {
      consider(encodeTwoIndexSets(source, winner.mode, winner.rotation, winner.indexSelection,
                                  effort, candidate));
    } else {
      consider(encodeOneIndexSet(source, winner.mode, winner.partition, effort, candidate));
    }
  }
  fixAnchors(best);
  packBc7Block(best, out);
}

}  // namespace relief::core::inline compression
