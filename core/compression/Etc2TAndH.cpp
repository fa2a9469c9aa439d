// ETC2's T and H modes (OpenGL ES 3.0, section C.1.5 "Format RGB ETC2"): two 4-bit-per-channel
// colours and one distance d from a table of eight. T paints c1, c2 + d, c2, c2 - d (one lone
// colour and a short grey line); H paints c1 +- d and c2 +- d (two short grey lines). They serve
// blocks of two distinct hues (an edge between materials), which ETC1's one-hue-per-half blocks
// can only average. The design follows etc2comp's and etcpak's: split the texels in two along
// their principal axis, seed each mode's colours from the two groups' means, try all eight
// distances, then refit the colours to the texels each paint colour won (least squares: a
// group's mean after its offsets are taken out) while the error falls. Every candidate is
// judged with the decoder's own clamping, and the packed winner by decodeEtc2Rgb itself.
#include "core/compression/BlockCodecs.h"
#include "core/compression/Etc2BlockBits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace relief::core::inline compression {
namespace {

// The texels as channel planes so the error loops vectorise; weight 0 marks texels outside the
// image.
struct Texels {
  float value[3][16];
  float weight[16];
};

struct TAndHCandidate {
  bool hMode = false;
  std::array<int, 3> c1{}, c2{};  // 4-bit colours, 0..15 per channel
  int distance = 0;               // index into kEtc2Distances
};

int quantise4(float value) {
  return std::clamp(int(std::lround(value / 17.0f)), 0, 15);
}

// The four paint colours as the decoder computes them (4-bit colours extended by x17, the
// distance added per channel and clamped to 0..255).
void paintColours(const TAndHCandidate& c, float paint[4][3]) {
  const int d = kEtc2Distances[c.distance];
  for (int ch = 0; ch < 3; ++ch) {
    const int one = c.c1[ch] * 17, two = c.c2[ch] * 17;
    if (c.hMode) {
      paint[0][ch] = float(std::min(one + d, 255));
      paint[1][ch] = float(std::max(one - d, 0));
      paint[2][ch] = float(std::min(two + d, 255));
      paint[3][ch] = float(std::max(two - d, 0));
    } else {
      paint[0][ch] = float(one);
      paint[1][ch] = float(std::min(two + d, 255));
      paint[2][ch] = float(two);
      paint[3][ch] = float(std::max(two - d, 0));
    }
  }
}

// Squared error of the block when each texel takes its nearest paint colour; the choices go to
// `index`.
float assignmentError(const Texels& texels, const TAndHCandidate& c, int index[16]) {
  float paint[4][3];
  paintColours(c, paint);
  float total = 0.0f;
  for (int t = 0; t < 16; ++t) {
    float best = std::numeric_limits<float>::max();
    int chosen = 0;
    for (int k = 0; k < 4; ++k) {
      float e = 0.0f;
      for (int ch = 0; ch < 3; ++ch) {
        const float diff = paint[k][ch] - texels.value[ch][t];
        e += diff * diff;
      }
      chosen = e < best ? k : chosen;
      best = std::min(best, e);
    }
    index[t] = chosen;
    total += texels.weight[t] * best;
  }
  return total;
}

// Least-squares colours for the texels' current choices: each colour is the mean of the texels
// that chose one of its paint colours, less the offset (+d, 0 or -d) that colour adds. A colour
// no texel chose keeps its value.
TAndHCandidate refit(const Texels& texels, const TAndHCandidate& c, const int index[16]) {
  const float d = float(kEtc2Distances[c.distance]);
  // Which colour (0: c1, 1: c2) and which offset each paint index stands for.
  const int owner[2][4] = {{0, 1, 1, 1}, {0, 0, 1, 1}};
  const float offset[2][4] = {{0.0f, d, 0.0f, -d}, {d, -d, d, -d}};
  const int mode = c.hMode ? 1 : 0;
  float sum[2][3] = {}, count[2] = {};
  for (int t = 0; t < 16; ++t) {
    const int k = index[t], o = owner[mode][k];
    count[o] += texels.weight[t];
    for (int ch = 0; ch < 3; ++ch)
      sum[o][ch] += texels.weight[t] * (texels.value[ch][t] - offset[mode][k]);
  }
  TAndHCandidate out = c;
  for (int ch = 0; ch < 3; ++ch) {
    if (count[0] > 0.0f)
      out.c1[ch] = quantise4(sum[0][ch] / count[0]);
    if (count[1] > 0.0f)
      out.c2[ch] = quantise4(sum[1][ch] / count[1]);
  }
  return out;
}

// The H mode's distance index has no bit of its own for its lowest bit: the decoder takes it
// from the order of the two colours (1 when c1 >= c2 as 12-bit numbers). Equal colours cannot
// express an even index.
int colourKey(const std::array<int, 3>& c) {
  return c[0] << 8 | c[1] << 4 | c[2];
}

bool expressible(const TAndHCandidate& c) {
  return !c.hMode || colourKey(c.c1) != colourKey(c.c2) || (c.distance & 1) == 1;
}

// Bit layouts as the decoder reads them (EtcCodec.cpp); the free bits select the mode
// (Etc2BlockBits.h).
void pack(TAndHCandidate c, int index[16], std::uint8_t out[8]) {
  std::uint64_t word = std::uint64_t(1) << 33;
  if (c.hMode) {
    if (((colourKey(c.c1) >= colourKey(c.c2)) ? 1 : 0) != (c.distance & 1)) {
      std::swap(c.c1, c.c2);
      for (int t = 0; t < 16; ++t)
        index[t] ^= 2;
    }
    putBits(word, c.c1[0], 62, 59);
    putBits(word, c.c1[1] >> 1, 58, 56);
    putBits(word, c.c1[1], 52, 52);
    putBits(word, c.c1[2] >> 3, 51, 51);
    putBits(word, c.c1[2], 49, 47);
    putBits(word, c.c2[0], 46, 43);
    putBits(word, c.c2[1], 42, 39);
    putBits(word, c.c2[2], 38, 35);
    putBits(word, c.distance >> 2, 34, 34);
    putBits(word, c.distance >> 1, 32, 32);
    keepDifferentialInRange(word, 63);        // red stays in 0..31
    forceDifferentialOverflow(word, 51, 50);  // green leaves it: H mode
  } else {
    putBits(word, c.c1[0] >> 2, 60, 59);
    putBits(word, c.c1[0], 57, 56);
    putBits(word, c.c1[1], 55, 52);
    putBits(word, c.c1[2], 51, 48);
    putBits(word, c.c2[0], 47, 44);
    putBits(word, c.c2[1], 43, 40);
    putBits(word, c.c2[2], 39, 36);
    putBits(word, c.distance >> 1, 35, 34);
    putBits(word, c.distance, 32, 32);
    forceDifferentialOverflow(word, 59, 58);  // red leaves 0..31: T mode
  }
  // Texel (x, y) keeps its index's high bit at 16 + x * 4 + y and its low bit at x * 4 + y.
  for (int t = 0; t < 16; ++t) {
    const int bit = (t % 4) * 4 + t / 4;
    putBits(word, index[t] >> 1, 16 + bit, 16 + bit);
    putBits(word, index[t], bit, bit);
  }
  storeBigEndian(word, out);
}

// Two groups of texels: the splits along the principal axis (the texels sorted by their
// projection, every cut between neighbours) with the smallest sum of squared distances to
// their groups' means, at most `wanted` of them. Returns masks of the first group.
std::vector<int> principalSplits(const Texels& texels, int validMask, int wanted) {
  float mean[3] = {}, count = 0.0f;
  for (int t = 0; t < 16; ++t) {
    count += texels.weight[t];
    for (int ch = 0; ch < 3; ++ch)
      mean[ch] += texels.weight[t] * texels.value[ch][t];
  }
  for (float& m : mean)
    m /= std::max(count, 1.0f);
  float covariance[3][3] = {};
  for (int t = 0; t < 16; ++t) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        covariance[i][j] +=
            texels.weight[t] * (texels.value[i][t] - mean[i]) * (texels.value[j][t] - mean[j]);
      }
    }
  }
  // Power iteration from the grey axis (ETC's offsets run along it, and it is never orthogonal
  // to a colour spread that matters).
  float axis[3] = {1.0f, 1.0f, 1.0f};
  for (int iteration = 0; iteration < 8; ++iteration) {
    float next[3] = {};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j)
        next[i] += covariance[i][j] * axis[j];
    }
    const float length = std::sqrt(next[0] * next[0] + next[1] * next[1] + next[2] * next[2]);
    if (length < 1e-6f)
      break;
    for (int i = 0; i < 3; ++i)
      axis[i] = next[i] / length;
  }
  std::array<int, 16> order{};
  int valid = 0;
  for (int t = 0; t < 16; ++t) {
    if ((validMask >> t) & 1)
      order[std::size_t(valid++)] = t;
  }
  const auto projection = [&](int t) {
    return axis[0] * texels.value[0][t] + axis[1] * texels.value[1][t] +
           axis[2] * texels.value[2][t];
  };
  std::sort(order.begin(), order.begin() + valid,
            [&](int a, int b) { return projection(a) < projection(b); });
  // Within-group squared distances from prefix sums of values and squares.
  std::vector<std::pair<float, int>> splits;
  float sumLow[3] = {}, squaresLow = 0.0f, sumAll[3] = {}, squaresAll = 0.0f;
  for (int i = 0; i < valid; ++i) {
    for (int ch = 0; ch < 3; ++ch) {
      const float v = texels.value[ch][order[std::size_t(i)]];
      sumAll[ch] += v;
      squaresAll += v * v;
    }
  }
  int mask = 0;
  for (int cut = 1; cut < valid; ++cut) {
    const int t = order[std::size_t(cut - 1)];
    mask |= 1 << t;
    for (int ch = 0; ch < 3; ++ch) {
      sumLow[ch] += texels.value[ch][t];
      squaresLow += texels.value[ch][t] * texels.value[ch][t];
    }
    float scatter = squaresAll;
    for (int ch = 0; ch < 3; ++ch) {
      const float high = sumAll[ch] - sumLow[ch];
      scatter -= sumLow[ch] * sumLow[ch] / float(cut) + high * high / float(valid - cut);
    }
    splits.emplace_back(scatter, mask);
  }
  const std::size_t kept = std::min<std::size_t>(splits.size(), std::size_t(wanted));
  std::partial_sort(splits.begin(), splits.begin() + std::ptrdiff_t(kept), splits.end());
  std::vector<int> masks;
  for (std::size_t i = 0; i < kept; ++i)
    masks.push_back(splits[i].second);
  return masks;
}

// How many of the eight distances, best first, are refitted at quality normal.
constexpr int kRefittedDistances = 2;

// The candidates a split of the block into two groups seeds: each group's mean colour at 4 bits,
// as H with the two groups and as T with either group as the lone colour.
std::array<TAndHCandidate, 3> seedsForSplit(const Texels& texels, int split) {
  float mean[2][3] = {}, count[2] = {};
  for (int t = 0; t < 16; ++t) {
    const int group = (split >> t) & 1;
    count[group] += texels.weight[t];
    for (int ch = 0; ch < 3; ++ch)
      mean[group][ch] += texels.weight[t] * texels.value[ch][t];
  }
  std::array<int, 3> quantised[2];
  for (int g = 0; g < 2; ++g) {
    for (int ch = 0; ch < 3; ++ch)
      quantised[g][ch] = quantise4(mean[g][ch] / std::max(count[g], 1.0f));
  }
  return {TAndHCandidate{true, quantised[0], quantised[1], 0},
          TAndHCandidate{false, quantised[0], quantised[1], 0},
          TAndHCandidate{false, quantised[1], quantised[0], 0}};
}

// The packed block's squared error judged by the decoder itself, in 0..255 units.
float decodedError(const std::uint8_t block[8], const float rgb[16][3], const Texels& texels) {
  float decoded[16][3];
  decodeEtc2Rgb(block, decoded);
  float error = 0.0f;
  for (int t = 0; t < 16; ++t) {
    for (int ch = 0; ch < 3; ++ch) {
      const float e = decoded[t][ch] * 255.0f - rgb[t][ch];
      error += texels.weight[t] * e * e;
    }
  }
  return error;
}

}  // namespace

float encodeEtc2TOrH(const float rgb[16][3], int validMask, CompressionQuality quality,
                     std::uint8_t out[8]) {
  Texels texels;
  for (int t = 0; t < 16; ++t) {
    texels.weight[t] = float((validMask >> t) & 1);
    for (int ch = 0; ch < 3; ++ch)
      texels.value[ch][t] = rgb[t][ch];
  }
  if (validMask == 0)
    validMask = 0xFFFF;
  // Best tries more splits and a final nudge of every stored value; measured in
  // tools/bench-compress.
  const bool best = quality == CompressionQuality::Best;
  const std::vector<int> splits = principalSplits(texels, validMask, best ? 3 : 1);
  const int refitted = best ? 8 : kRefittedDistances;
  TAndHCandidate winner;
  float winnerError = std::numeric_limits<float>::max();
  int index[16];
  const auto consider = [&](const TAndHCandidate& c) {
    if (!expressible(c))
      return std::numeric_limits<float>::max();
    const float error = assignmentError(texels, c, index);
    if (error < winnerError) {
      winnerError = error;
      winner = c;
    }
    return error;
  };
  for (int split : splits) {
    const std::array<TAndHCandidate, 3> seeds = seedsForSplit(texels, split);
    for (TAndHCandidate seed : seeds) {
      // Every distance from the seed, then the most promising refitted.
      std::array<std::pair<float, int>, 8> byError;
      for (int distance = 0; distance < 8; ++distance) {
        seed.distance = distance;
        byError[std::size_t(distance)] = {consider(seed), distance};
      }
      std::partial_sort(byError.begin(), byError.begin() + refitted, byError.end());
      for (int r = 0; r < refitted; ++r) {
        seed.distance = byError[std::size_t(r)].second;
        TAndHCandidate current = seed;
        float error = byError[std::size_t(r)].first;
        // Refit while it helps (two rounds reach nearly all of the gain).
        for (int round = 0; round < 2 && error < std::numeric_limits<float>::max(); ++round) {
          assignmentError(texels, current, index);
          const TAndHCandidate next = refit(texels, current, index);
          const float nextError = consider(next);
          if (nextError >= error)
            break;
          current = next;
          error = nextError;
        }
      }
    }
  }
  if (best) {
    // Nudge each stored channel a step while the error falls.
    for (int sweep = 0; sweep < 2; ++sweep) {
      const float before = winnerError;
      for (int which = 0; which < 2; ++which) {
        for (int ch = 0; ch < 3; ++ch) {
          for (int step : {-1, 1}) {
            TAndHCandidate trial = winner;
            int& value = which == 0 ? trial.c1[ch] : trial.c2[ch];
            value = std::clamp(value + step, 0, 15);
            consider(trial);
          }
        }
      }
      if (winnerError >= before)
        break;
    }
  }
  assignmentError(texels, winner, index);
  pack(winner, index, out);
  return decodedError(out, rgb, texels);
}

}  // namespace relief::core::inline compression
