// BC1 colour blocks of our own (BlockCodecs.h: BC1, and the colour half of BC2, BC3 and
// DXT5nm), replacing libsquish's cluster fit, which is slow (about 1 MPix/s on two cores): the
// design follows the fast encoders that match it (rgbcx, stb_dxt). Endpoints start at the
// extremes of the texels' principal axis and are refined by least squares over the chosen
// indices; then a bounded cluster search moves the boundaries between the four (or, in BC1's
// three-colour mode, three) groups of texels taken in order along the axis, a step or two from
// where the refinement left them, solving each grouping by least squares from prefix sums, which
// is squish's cluster fit restricted to the groupings near the answer; then the quantised
// endpoints are nudged a step at a time while the error falls. Every candidate is judged by the
// error of its quantised 5:6:5 endpoints as the GPU decodes them (squish judges the unquantised
// ones). Blocks of one colour use tables of the best endpoint pair per value.
//
// Error is the sum of squared 8-bit differences with channel weights: uniform (as libsquish
// and rgbcx default, so PSNR compares) or luminance weights when asked for.
#include "core/compression/BlockCodecs.h"

#include <algorithm>
#include <cmath>
#include <limits>

// Floating-point contraction off: the AVX-512 copy of the encoder below must round as the
// default one does (FMA instructions would fuse its multiply-adds), so a map compresses to the
// same bytes on every x86-64 machine. Pushed and popped: a unity build compiles other files after
// this one.
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")

namespace relief::core::inline compression {
namespace {

struct Bc1Effort {
  int refinePasses;
  int clusterRadius;  // boundaries tried within this distance of the refined ones (0: none)
  // The cluster search runs where the refined fit's mean squared error per texel and channel
  // (8-bit levels, unit weight) exceeds this: below it the fit is within two levels RMS and
  // the search rarely finds better.
  float clusterAbove;
  // BC1's three-colour mode is tried where the four-colour fit's mean squared error per texel
  // and channel (in 8-bit levels, at unit weight) exceeds this; never when negative.
  float threeColourAbove;
  int perturbSweeps;  // sweeps nudging the quantised endpoints a step at a time (0: none)
  // The cluster search's splits quantised and evaluated, best (unquantised) first. Splits that
  // put the same two groups of texels on different levels tie unquantised (both reproduce the
  // groups' means) but not once quantised: a group on a third-way level lets the endpoints
  // land further out, where 5:6:5 steps cost less.
  int splitsEvaluated;
  // Best: the nudges also move a channel's two endpoints together (a step each, either way),
  // and both the four- and the three-colour fit are nudged before they are compared.
  bool thorough;
};
// Measured on a 2048x2048 mosaic of twelve photographs and four game colour maps
// (tools/bench-cli's; uniform weights, one core): normal 36.37 dB in 2.2 us per block, 1.6 us
// since the rank sort in principalAxis, validSum and the telescoped cluster moments (best was
// 36.42 dB in 4.9 us before the search below), against libsquish's cluster fit's 36.41 dB in
// 14.8 us. In normal, one
// perturbation sweep and the three-colour mode where the error is large (an RMS of 4.6 levels
// and up) give 36.37 dB; two sweeps and no three-colour mode gave 36.35 dB in 13% more time.
// Trying the three-colour mode on every block cost 19% more time for 36.38 dB: on blocks
// with small errors it wins before perturbation and then blocks a better four-colour fit.
// Skipping the cluster search where the refined fit's error is below 10/3 (an RMS of 1.8
// levels) saved 10% of normal's time at the same 36.366 dB; below 20/3, 16% for 36.364 dB;
// skipping perturbation the same way cost 0.04 dB for 14%, so it stays.
// Best searches further to meet crunch 1.04's (-dxtQuality uber, uniform metrics) quality:
// every split of the texels along the axis (the cluster boundaries anywhere), the 48 best splits
// quantised and evaluated (splits that put the same groups on different levels tie before
// quantisation, and the winner is often the one whose endpoints land outside the groups), joint
// nudges of a channel's two endpoints, up to 16 sweeps, and the four- and three-colour fits
// each nudged before they are compared. On five scikit-image photographs best went from 36.05
// to 36.11 dB with boundaries 8 texels from the refined ones and two splits evaluated, and to
// 36.13 dB with this (crunch 36.14 dB); on the mosaic 36.42 -> 36.49 -> 36.51 dB in 4.9 s
// (crunch 36.53 dB in 14.6 s). Steps of two, and a second cluster search with the texels sorted
// along the best fit's direction (squish's iteration), gained nothing more; 160 splits gained
// 0.003 dB more for twice the time.
constexpr Bc1Effort kBc1Efforts[3] = {
    {1, 0, 0.0f, -1.0f, 0, 2, false},
    {1, 1, 10.0f / 3.0f, 64.0f / 3.0f, 1, 2, false},
    {3, 16, 0.0f, 0.0f, 16, 48, true},
};

constexpr int expand5(int v) {
  return (v << 3) | (v >> 2);
}
constexpr int expand6(int v) {
  return (v << 2) | (v >> 4);
}

// The nearest 5- and 6-bit values of each 8-bit value, as they decode. Built at compile time:
// as a function's static, every quantise paid its guard's check.
struct NearestTables {
  std::uint8_t five[256] = {}, six[256] = {};
};
constexpr NearestTables makeNearestTables() {
  const auto distance = [](int a, int b) { return a < b ? b - a : a - b; };
  NearestTables tables;
  for (int v = 0; v < 256; ++v) {
    int best5 = 0, best6 = 0;
    for (int q = 0; q < 64; ++q) {
      if (q < 32 && distance(expand5(q), v) < distance(expand5(best5), v))
        best5 = q;
      if (distance(expand6(q), v) < distance(expand6(best6), v))
        best6 = q;
    }
    tables.five[v] = std::uint8_t(best5);
    tables.six[v] = std::uint8_t(best6);
  }
  return tables;
}
constexpr NearestTables kNearest = makeNearestTables();

// A 5:6:5 endpoint, unpacked.
struct Endpoint {
  int q[3];  // 5, 6, 5 bits
  std::uint16_t packed() const { return std::uint16_t(q[0] << 11 | q[1] << 5 | q[2]); }
  void decoded(int out[3]) const {
    out[0] = expand5(q[0]);
    out[1] = expand6(q[1]);
    out[2] = expand5(q[2]);
  }
};

Endpoint quantise(const float colour[3]) {
  Endpoint e;
  for (int c = 0; c < 3; ++c) {
    const int v = std::clamp(int(colour[c] + 0.5f), 0, 255);  // colour is never negative
    e.q[c] = c == 1 ? kNearest.six[v] : kNearest.five[v];
  }
  return e;
}

struct Source {
  float px[16][3];     // 0..255
  float plane[3][16];  // the same, channel by channel
  float valid[16];     // 1 inside the image, 0 for edge padding
  int order[16];       // valid texels
  int count = 0;
  std::uint16_t validMask = 0;
  float weight[3];
};

struct Candidate {
  Endpoint e0{}, e1{};
  bool fourColour = true;
  float error = std::numeric_limits<float>::max();
  std::uint8_t level[16] = {};  // 0 at e0 .. 3 (or 2 in three-colour mode) at e1, per texel
};

// Palette by level (e0 first, e1 last), as decodeColour in BcCodec.cpp decodes it: thirds and
// halves rounded down.
int paletteOf(const Endpoint& e0, const Endpoint& e1, bool fourColour, int palette[4][3]) {
  int a[3], b[3];
  e0.decoded(a);
  e1.decoded(b);
  for (int c = 0; c < 3; ++c) {
    palette[0][c] = a[c];
    if (fourColour) {
      palette[1][c] = (2 * a[c] + b[c]) / 3;
      palette[2][c] = (a[c] + 2 * b[c]) / 3;
      palette[3][c] = b[c];
    } else {
      palette[1][c] = (a[c] + b[c]) / 2;
      palette[2][c] = b[c];
    }
  }
  return fourColour ? 4 : 3;
}

// The sum of a value per texel over the valid texels, in four interleaved partial sums so that
// it vectorises: added one after another, the sixteen dependent additions were the longest
// chain of an evaluation. (The order changes the sum's last bit at most; for whole-number
// texels at uniform weights, whose errors are whole numbers below 2^24, not at all.)
float validSum(const Source& source, const float values[16]) {
  float lane[4];
  for (int l = 0; l < 4; ++l)
    lane[l] = values[l] * source.valid[l];
  for (int t = 4; t < 16; t += 4) {
    for (int l = 0; l < 4; ++l)
      lane[l] += values[t + l] * source.valid[t + l];
  }
  return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

// Nearest palette entry for every texel (all 16: edge texels need indices too), the weighted
// error over the valid ones. The texel loops run over channel planes (Source::plane), so the
// compiler vectorises them: this is where the encoder spends its time.
void evaluate(const Source& source, const Endpoint& e0, const Endpoint& e1, bool fourColour,
              Candidate& best) {
  int palette[4][3];
  const int levels = paletteOf(e0, e1, fourColour, palette);
  float bestError[16];
  std::uint8_t level[16];
  for (int l = 0; l < levels; ++l) {
    const float p0 = float(palette[l][0]), p1 = float(palette[l][1]), p2 = float(palette[l][2]);
    for (int t = 0; t < 16; ++t) {
      const float d0 = source.plane[0][t] - p0, d1 = source.plane[1][t] - p1,
                  d2 = source.plane[2][t] - p2;
      const float error =
          source.weight[0] * d0 * d0 + source.weight[1] * d1 * d1 + source.weight[2] * d2 * d2;
      const bool better = l == 0 || error < bestError[t];
      bestError[t] = better ? error : bestError[t];
      level[t] = better ? std::uint8_t(l) : level[t];
    }
  }
  const float total = validSum(source, bestError);
  if (total < best.error) {
    best.error = total;
    best.e0 = e0;
    best.e1 = e1;
    best.fourColour = fourColour;
    std::copy(level, level + 16, best.level);
  }
}

// Least squares for the endpoints given each valid texel's level: texel = (1 - w) e0 + w e1.
bool leastSquares(const Source& source, const Candidate& fit, float e0[3], float e1[3]) {
  const float steps = fit.fourColour ? 3.0f : 2.0f;
  float aa = 0, ab = 0, bb = 0, ax[3] = {}, bx[3] = {};
  for (int k = 0; k < source.count; ++k) {
    const int t = source.order[k];
    const float w = float(fit.level[t]) / steps, v = 1.0f - w;
    aa += v * v;
    ab += v * w;
    bb += w * w;
    for (int c = 0; c < 3; ++c) {
      ax[c] += v * source.px[t][c];
      bx[c] += w * source.px[t][c];
    }
  }
  const float determinant = aa * bb - ab * ab;
  if (std::abs(determinant) < 1e-6f)
    return false;
  for (int c = 0; c < 3; ++c) {
    e0[c] = std::clamp((bb * ax[c] - ab * bx[c]) / determinant, 0.0f, 255.0f);
    e1[c] = std::clamp((aa * bx[c] - ab * ax[c]) / determinant, 0.0f, 255.0f);
  }
  return true;
}

void refine(const Source& source, int passes, Candidate& best) {
  for (int pass = 0; pass < passes && best.error > 0.0f; ++pass) {
    const float before = best.error;
    float e0[3], e1[3];
    if (!leastSquares(source, best, e0, e1))
      return;
    evaluate(source, quantise(e0), quantise(e1), best.fourColour, best);
    if (best.error >= before)
      return;
  }
}

// The texels' principal axis (in weighted space), the valid texels sorted along it, and the two
// extreme points of their projections, in colour space.
void principalAxis(const Source& source, int sorted[16], float e0[3], float e1[3]) {
  float mean[3] = {};
  for (int k = 0; k < source.count; ++k) {
    for (int c = 0; c < 3; ++c)
      mean[c] += source.px[source.order[k]][c];
  }
  for (float& m : mean)
    m /= float(source.count);
  float cov[3][3] = {};
  const float root[3] = {std::sqrt(source.weight[0]), std::sqrt(source.weight[1]),
                         std::sqrt(source.weight[2])};
  for (int k = 0; k < source.count; ++k) {
    float d[3];
    for (int c = 0; c < 3; ++c)
      d[c] = (source.px[source.order[k]][c] - mean[c]) * root[c];
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j)
        cov[i][j] += d[i] * d[j];
    }
  }
  cov[1][0] = cov[0][1];
  cov[2][0] = cov[0][2];
  cov[2][1] = cov[1][2];
  int start = 0;
  for (int c = 1; c < 3; ++c) {
    if (cov[c][c] > cov[start][start])
      start = c;
  }
  float axis[3] = {cov[start][0], cov[start][1], cov[start][2]};
  for (int iteration = 0; iteration < 4; ++iteration) {
    float next[3];
    for (int i = 0; i < 3; ++i)
      next[i] = cov[i][0] * axis[0] + cov[i][1] * axis[1] + cov[i][2] * axis[2];
    const float length = std::max({std::abs(next[0]), std::abs(next[1]), std::abs(next[2])});
    if (length <= 0.0f)
      break;
    for (int c = 0; c < 3; ++c)
      axis[c] = next[c] / length;
  }
  // Back to colour space: the direction in which the weighted error grows along the axis.
  float direction[3], length = 0.0f;
  for (int c = 0; c < 3; ++c) {
    direction[c] = root[c] > 0.0f ? axis[c] / root[c] : 0.0f;
    length += direction[c] * direction[c];
  }
  if (length > 0.0f) {
    length = std::sqrt(length);
    for (float& d : direction)
      d /= length;
  }
  float t[16];
  for (int k = 0; k < source.count; ++k) {
    const float* px = source.px[source.order[k]];
    t[k] = (px[0] - mean[0]) * direction[0] + (px[1] - mean[1]) * direction[1] +
           (px[2] - mean[2]) * direction[2];
  }
  // A stable sort by rank: each texel's place is the number of texels before it in the order
  // (smaller, or equal and earlier). Sixteen values compared all with all, without branches:
  // an insertion sort's mispredicted branches were a quarter of this function's time.
  float low = t[0], high = t[0];
  for (int k = 0; k < source.count; ++k) {
    int rank = 0;
    for (int j = 0; j < source.count; ++j)
      rank += int(t[j] < t[k]) + int(t[j] == t[k] && j < k);
    sorted[rank] = source.order[k];
    low = std::min(low, t[k]);
    high = std::max(high, t[k]);
  }
  for (int c = 0; c < 3; ++c) {
    e0[c] = std::clamp(mean[c] + low * direction[c], 0.0f, 255.0f);
    e1[c] = std::clamp(mean[c] + high * direction[c], 0.0f, 255.0f);
  }
}

// Cluster search around a fit: the texels in axis order are split into `levels` runs (run k
// takes level k); runs whose boundaries lie within `radius` of the fit's level counts are
// solved by least squares from prefix sums, and the best `splitsEvaluated` by that (unquantised)
// error are quantised and evaluated.
void clusterSearch(const Source& source, const int sorted[16], int levels, int radius,
                   int splitsEvaluated, Candidate& best) {
  const int n = source.count;
  float prefix[17][3] = {}, squares = 0.0f;
  for (int k = 0; k < n; ++k) {
    for (int c = 0; c < 3; ++c) {
      prefix[k + 1][c] = prefix[k][c] + source.px[sorted[k]][c];
      squares += source.weight[c] * source.px[sorted[k]][c] * source.px[sorted[k]][c];
    }
  }
  // Where the fit's runs end, counting its texels per level (levels in run order).
  int counts[4] = {};
  if (best.fourColour == (levels == 4)) {
    for (int k = 0; k < n; ++k)
      ++counts[best.level[sorted[k]]];
  } else {
    // From the other mode: split evenly to start.
    for (int l = 0; l < levels; ++l)
      counts[l] = n * (l + 1) / levels - n * l / levels;
  }
  int boundary[3] = {counts[0], counts[0] + counts[1], counts[0] + counts[1] + counts[2]};
  const float steps = float(levels - 1);
  // The least-squares moments of a split (texel runs ending at `ends`): texel = v e0 + w e1
  // with w = level / steps, summed over the runs. As v + w = 1, bx = (sum of the texels) - ax,
  // and ax telescopes: the sum over the runs of v (prefix[end] - prefix[begin]) is the sum of
  // prefix[end] over every run but the last, over steps (three loads a channel instead of a
  // loop over the runs: the search evaluates up to 27 splits a block).
  struct Moments {
    float aa = 0, ab = 0, bb = 0, ax[3] = {}, bx[3] = {};
    float determinant() const { return aa * bb - ab * ab; }
  };
  const float inverseSteps = 1.0f / steps;
  const auto momentsOf = [&](const int ends[4]) {
    Moments m;
    int begin = 0;
    for (int l = 0; l < levels; ++l) {
      const float count = float(ends[l] - begin);
      const float w = float(l) * inverseSteps, v = 1.0f - w;
      m.aa += count * v * v;
      m.ab += count * v * w;
      m.bb += count * w * w;
      begin = ends[l];
    }
    for (int c = 0; c < 3; ++c) {
      float inner = prefix[ends[0]][c];
      for (int l = 1; l < levels - 1; ++l)
        inner += prefix[ends[l]][c];
      m.ax[c] = inner * inverseSteps;
      m.bx[c] = prefix[n][c] - m.ax[c];
    }
    return m;
  };
  struct Split {
    float error;
    int ends[4];
  };
  constexpr int kMaxSplits = 48;
  Split top[kMaxSplits];
  const int kept = std::min(splitsEvaluated, kMaxSplits);
  for (int i = 0; i < kept; ++i)
    top[i].error = std::numeric_limits<float>::max();
  const int splits = levels - 1;
  int lo[3], hi[3];
  for (int s = 0; s < 3; ++s) {
    lo[s] = s < splits ? std::max(0, boundary[s] - radius) : n;
    hi[s] = s < splits ? std::min(n, boundary[s] + radius) : n;
  }
  for (int b0 = lo[0]; b0 <= hi[0]; ++b0) {
    for (int b1 = std::max(lo[1], b0); b1 <= hi[1]; ++b1) {
      for (int b2 = std::max(lo[2], b1); b2 <= hi[2]; ++b2) {
        const Split candidate{0.0f, {b0, splits >= 2 ? b1 : n, splits >= 3 ? b2 : n, n}};
        const Moments m = momentsOf(candidate.ends);
        const float determinant = m.determinant();
        if (std::abs(determinant) < 1e-6f)
          continue;
        // At the least-squares optimum the error is sum x^2 - [ax bx] M^-1 [ax bx]^T per
        // channel; the endpoints themselves are solved only for the two best splits.
        float error = squares;
        const float inverse = 1.0f / determinant;
        for (int c = 0; c < 3; ++c) {
          error -= source.weight[c] * inverse *
                   (m.bb * m.ax[c] * m.ax[c] - 2.0f * m.ab * m.ax[c] * m.bx[c] +
                    m.aa * m.bx[c] * m.bx[c]);
        }
        if (error < top[kept - 1].error) {
          int at = kept - 1;
          for (; at > 0 && top[at - 1].error > error; --at)
            top[at] = top[at - 1];
          top[at] = candidate;
          top[at].error = error;
        }
      }
    }
  }
  for (int i = 0; i < kept; ++i) {
    const Split& split = top[i];
    if (split.error == std::numeric_limits<float>::max())
      continue;
    const Moments m = momentsOf(split.ends);
    const float inverse = 1.0f / m.determinant();
    float e0[3], e1[3];
    for (int c = 0; c < 3; ++c) {
      e0[c] = std::clamp((m.bb * m.ax[c] - m.ab * m.bx[c]) * inverse, 0.0f, 255.0f);
      e1[c] = std::clamp((m.aa * m.bx[c] - m.ab * m.ax[c]) * inverse, 0.0f, 255.0f);
    }
    evaluate(source, quantise(e0), quantise(e1), levels == 4, best);
  }
}

// Steps each stored endpoint channel by one while the error falls, indices following. A step
// changes one channel's palette values only, so each channel's share of every texel's error at
// every level is kept, and a step recomputes one share (a third of a full evaluation).
void perturb(const Source& source, int sweeps, bool joint, Candidate& best) {
  const int levels = best.fourColour ? 4 : 3;
  float share[3][4][16];
  const auto channelShare = [&](int c, int q0, int q1, float out[4][16]) {
    const int a = c == 1 ? expand6(q0) : expand5(q0), b = c == 1 ? expand6(q1) : expand5(q1);
    const float values[4] = {float(a), float(levels == 4 ? (2 * a + b) / 3 : (a + b) / 2),
                             float(levels == 4 ? (a + 2 * b) / 3 : b), float(b)};
    for (int l = 0; l < levels; ++l) {
      for (int t = 0; t < 16; ++t) {
        const float d = source.plane[c][t] - values[l];
        out[l][t] = source.weight[c] * d * d;
      }
    }
  };
  for (int c = 0; c < 3; ++c)
    channelShare(c, best.e0.q[c], best.e1.q[c], share[c]);
  // The error with channel `c`'s shares replaced by `trial`, the other two channels' shares
  // summed once per channel in `others` (texels innermost and floats only, so that it
  // vectorises; the levels are found again only for a step that is kept).
  float others[4][16];
  const auto sumOthers = [&](int c) {
    const float(&first)[4][16] = share[c == 0 ? 1 : 0];
    const float(&second)[4][16] = share[c == 2 ? 1 : 2];
    for (int l = 0; l < levels; ++l) {
      for (int t = 0; t < 16; ++t)
        others[l][t] = first[l][t] + second[l][t];
    }
  };
  const auto total = [&](const float(&trial)[4][16]) {
    float low[16];
    for (int t = 0; t < 16; ++t)
      low[t] = trial[0][t] + others[0][t];
    for (int l = 1; l < levels; ++l) {
      for (int t = 0; t < 16; ++t)
        low[t] = std::min(low[t], trial[l][t] + others[l][t]);
    }
    return validSum(source, low);
  };
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    const float before = best.error;
    for (int c = 0; c < 3; ++c) {
      sumOthers(c);
      // Steps of (e0, e1): one endpoint at a time, then (joint) both together.
      static constexpr int kSteps[8][2] = {{-1, 0},  {1, 0}, {0, -1}, {0, 1},
                                           {-1, -1}, {1, 1}, {-1, 1}, {1, -1}};
      for (int k = 0; k < (joint ? 8 : 4); ++k) {
        Endpoint e0 = best.e0, e1 = best.e1;
        e0.q[c] += kSteps[k][0];
        e1.q[c] += kSteps[k][1];
        const int top = c == 1 ? 63 : 31;
        if (e0.q[c] < 0 || e0.q[c] > top || e1.q[c] < 0 || e1.q[c] > top)
          continue;
        float trial[4][16];
        channelShare(c, e0.q[c], e1.q[c], trial);
        if (total(trial) < best.error) {
          best.error = std::numeric_limits<float>::max();
          evaluate(source, e0, e1, best.fourColour, best);  // the levels, and the same error
          std::copy(&trial[0][0], &trial[0][0] + 64, &share[c][0][0]);
        }
      }
    }
    if (best.error >= before || best.error == 0.0f)
      return;
  }
}

// Blocks of one colour: per channel and value, the endpoint pair whose one-third point decodes
// nearest it (stb_dxt's "optimal single colour" tables, built here for our decoder's rounding).
struct SingleColourTables {
  std::uint8_t five[256][2], six[256][2];
  SingleColourTables() {
    for (int v = 0; v < 256; ++v) {
      int best5 = 1 << 30, best6 = 1 << 30;
      for (int a = 0; a < 64; ++a) {
        for (int b = 0; b < 64; ++b) {
          if (a < 32 && b < 32) {
            const int d = std::abs((2 * expand5(a) + expand5(b)) / 3 - v);
            if (d < best5) {
              best5 = d;
              five[v][0] = std::uint8_t(a);
              five[v][1] = std::uint8_t(b);
            }
          }
          const int d = std::abs((2 * expand6(a) + expand6(b)) / 3 - v);
          if (d < best6) {
            best6 = d;
            six[v][0] = std::uint8_t(a);
            six[v][1] = std::uint8_t(b);
          }
        }
      }
    }
  }
};
const SingleColourTables& singleColour() {
  static const SingleColourTables tables;
  return tables;
}

void writeBlock(const Candidate& fit, bool bc1, std::uint8_t* out) {
  std::uint16_t c0 = fit.e0.packed(), c1 = fit.e1.packed();
  std::uint8_t level[16];
  std::copy(fit.level, fit.level + 16, level);
  // Index of each level: e0 is index 0, e1 index 1; in four-colour mode the thirds are 2 and 3,
  // in three-colour mode the half is 2.
  const bool fourColour = fit.fourColour || !bc1;
  bool swap = false;
  if (bc1 && fourColour && c0 <= c1) {
    if (c0 == c1) {
      std::fill(level, level + 16, std::uint8_t(0));  // one colour: any mode decodes index 0
    } else {
      swap = true;  // four colours need c0 > c1 in BC1
    }
  } else if (bc1 && !fourColour && c0 > c1) {
    swap = true;  // three colours need c0 <= c1
  }
  if (swap) {
    std::swap(c0, c1);
    for (std::uint8_t& l : level)
      l = std::uint8_t((fourColour ? 3 : 2) - l);
  }
  static constexpr std::uint8_t kFourIndex[4] = {0, 2, 3, 1};
  static constexpr std::uint8_t kThreeIndex[3] = {0, 2, 1};
  out[0] = std::uint8_t(c0);
  out[1] = std::uint8_t(c0 >> 8);
  out[2] = std::uint8_t(c1);
  out[3] = std::uint8_t(c1 >> 8);
  for (int row = 0; row < 4; ++row) {
    std::uint8_t bits = 0;
    for (int x = 0; x < 4; ++x) {
      const int l = level[row * 4 + x];
      bits = std::uint8_t(bits | (fourColour ? kFourIndex[l] : kThreeIndex[l]) << (2 * x));
    }
    out[4 + row] = bits;
  }
}

}  // namespace

// Compiled twice, for x86-64-v4 (AVX-512) and for any x86-64, the copy picked when the program
// loads; `flatten` inlines every helper into each copy so each is vectorised for its own
// instructions (a block's 16 texels fill one 512-bit register where SSE2 needs four). Measured
// on the 2048^2 mosaic, one core, fastest of six alternating runs on the shared machine: 1.64 us
// a block as plain x86-64, 1.55 us with the AVX-512 copy, the same bytes.
__attribute__((flatten, target_clones("arch=x86-64-v4", "default"))) void encodeBc1Colour(
    const float rgb[16][3], int validMask, CompressionQuality quality, bool perceptual, bool bc1,
    std::uint8_t* out) {
  const Bc1Effort& effort = kBc1Efforts[int(quality)];
  Source source;
  source.validMask = std::uint16_t(validMask == 0 ? 0xFFFF : validMask);
  const float uniform[3] = {1.0f, 1.0f, 1.0f};
  // Rec. 709 luminance weights, as libsquish's perceptual metric uses them.
  const float luminance[3] = {0.2126f, 0.7152f, 0.0722f};
  std::copy_n(perceptual ? luminance : uniform, 3, source.weight);
  for (int t = 0; t < 16; ++t) {
    for (int c = 0; c < 3; ++c)
      source.plane[c][t] = source.px[t][c] = std::clamp(rgb[t][c], 0.0f, 255.0f);
    source.valid[t] = (source.validMask >> t) & 1 ? 1.0f : 0.0f;
    if ((source.validMask >> t) & 1)
      source.order[source.count++] = t;
  }

  Candidate best;
  // One colour: the single-colour tables (exact or nearest for each channel at index 2).
  bool flat = true;
  for (int k = 1; k < source.count && flat; ++k) {
    for (int c = 0; c < 3; ++c)
      flat = flat && int(std::lround(source.px[source.order[k]][c])) ==
                         int(std::lround(source.px[source.order[0]][c]));
  }
  if (flat) {
    const float* px = source.px[source.order[0]];
    Endpoint e0, e1;
    for (int c = 0; c < 3; ++c) {
      const int v = std::clamp(int(std::lround(px[c])), 0, 255);
      const std::uint8_t* pair = c == 1 ? singleColour().six[v] : singleColour().five[v];
      e0.q[c] = pair[0];
      e1.q[c] = pair[1];
    }
    evaluate(source, e0, e1, true, best);
    evaluate(source, quantise(px), quantise(px), true, best);
    writeBlock(best, bc1, out);
    return;
  }

  int sorted[16];
  float e0[3], e1[3];
  principalAxis(source, sorted, e0, e1);
  evaluate(source, quantise(e0), quantise(e1), true, best);
  refine(source, effort.refinePasses, best);
  const float weightSum = source.weight[0] + source.weight[1] + source.weight[2];
  if (effort.clusterRadius > 0 && best.error > 0.0f &&
      best.error > effort.clusterAbove * weightSum * float(source.count)) {
    clusterSearch(source, sorted, 4, effort.clusterRadius, effort.splitsEvaluated, best);
    refine(source, 1, best);
  }
  if (effort.thorough && best.error > 0.0f)
    perturb(source, effort.perturbSweeps, true, best);
  if (bc1 && effort.threeColourAbove >= 0.0f &&
      best.error > effort.threeColourAbove * weightSum * float(source.count)) {
    // The three-colour mode (half-way point, no black: Relief's BC1 is opaque) where it wins.
    Candidate three;
    evaluate(source, quantise(e0), quantise(e1), false, three);
    refine(source, effort.refinePasses, three);
    clusterSearch(source, sorted, 3, std::max(effort.clusterRadius, 1), effort.splitsEvaluated,
                  three);
    if (effort.thorough && three.error > 0.0f)
      perturb(source, effort.perturbSweeps, true, three);
    if (three.error < best.error)
      best = three;
  }
  if (!effort.thorough && effort.perturbSweeps > 0 && best.error > 0.0f)
    perturb(source, effort.perturbSweeps, false, best);
  writeBlock(best, bc1, out);
}

}  // namespace relief::core::inline compression

#pragma GCC pop_options
