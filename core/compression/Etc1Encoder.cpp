// ETC1's individual and differential modes (OpenGL ES 3.0, section C.1.3 "Format RGB ETC1", and
// ETC2's reading of the same bits): the block splits into two 2x4 halves (side by side, or one
// above the other when flipped); each half has a base colour (4 bits a channel, or 5 bits with
// the second half a signed 3-bit step from the first) and one of eight modifier tables, and each
// texel adds one of its table's four modifiers to all three channels.
//
// android-libetc1, which Relief used before, takes each half's mean colour as its base and only
// picks the table, which left Relief's ETC2 0.2-0.5 dB below PVRTexTool's etcfast
// (tools/bench-etc2). This search moves the base too. A modifier adds the same m to every
// channel, so without the decoder's clamp a texel p's error under base b is
//   |b - p|^2 + 2 m (B - P) + 3 m^2,   B and P the sums of b's and p's channels,
// and over a half: N|b|^2 - 2 b.S + Q (from the half's sums) plus, per texel, the least of
// 3 m^2 + 2 m (B - P) over the table's four modifiers, which depends on the base only through B
// (the "model" below). For each table the search finds where the least-squares base lies for the
// modifiers its texels pick (a grey shift from the mean), looks along the grey diagonal from
// there, then around the best tables' bases in every channel, computing the per-texel part once
// per distinct B. Where the clamp can touch a base (near black or white, or a wide table), the
// base is judged texel by texel with the clamp instead, since there the best bases leave the
// grey line. The best halves are paired under the differential step's reach (-4..3 a channel),
// else searched again inside it, else coded in the individual mode; each flip's winner is
// packed with each texel's modifier chosen as the decoder clamps, and judged exactly.
#include "core/compression/BlockCodecs.h"
#include "core/compression/Etc2BlockBits.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace relief::core::inline compression {
namespace {

// The valid texels of one half.
struct Etc1Half {
  int count = 0;
  float colour[3][8] = {};  // channel planes, so the per-texel loops vectorise
  float grey[8];            // sum of the channels
  float sum[3] = {0.0f, 0.0f, 0.0f};
  float sumOfSquares = 0.0f;
  float mean[3] = {0.0f, 0.0f, 0.0f};
};

// A half's base (quantised levels) and table, with its error as searched.
struct Etc1HalfChoice {
  std::array<int, 3> level{};
  int table = 0;
  float error = std::numeric_limits<float>::max();
};

// The few best distinct bases of a half, best first.
constexpr int kKeptBases = 6;
struct Etc1HalfCandidates {
  std::array<Etc1HalfChoice, kKeptBases> choice;
  int size = 0;

  void offer(const Etc1HalfChoice& c) {
    for (int i = 0; i < size; ++i) {
      if (choice[i].level == c.level) {
        if (c.error >= choice[i].error)
          return;
        // The same base with a better table: drop the old entry, insert below.
        std::copy(choice.begin() + i + 1, choice.begin() + size, choice.begin() + i);
        --size;
        break;
      }
    }
    if (size == kKeptBases && c.error >= choice[size - 1].error)
      return;
    int at = std::min(size, kKeptBases - 1);
    while (at > 0 && choice[at - 1].error > c.error) {
      choice[at] = choice[at - 1];
      --at;
    }
    choice[at] = c;
    size = std::min(size + 1, kKeptBases);
  }
};

// The level range of a base: 4 bits (individual) or 5 (differential).
struct Etc1Precision {
  int bits;
  int top() const { return (1 << bits) - 1; }
  int expand(int level) const { return bits == 4 ? level * 17 : (level << 3 | level >> 2); }
  int quantise(float value) const {
    return std::clamp(int(std::lround(value * float(top()) / 255.0f)), 0, top());
  }
};

// A box of allowed levels per channel (the differential step's reach from the other half).
struct Etc1LevelBox {
  std::array<int, 3> low{0, 0, 0}, high{31, 31, 31};
};

Etc1Half halfOf(const float rgb[16][3], int validMask, bool flip, int half) {
  Etc1Half h;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const int t = y * 4 + x;
      if ((flip ? y / 2 : x / 2) != half || !((validMask >> t) & 1))
        continue;
      float grey = 0.0f;
      for (int c = 0; c < 3; ++c) {
        h.colour[c][h.count] = rgb[t][c];
        h.sum[c] += rgb[t][c];
        h.sumOfSquares += rgb[t][c] * rgb[t][c];
        grey += rgb[t][c];
      }
      h.grey[h.count++] = grey;
    }
  }
  for (int c = 0; c < 3 && h.count > 0; ++c)
    h.mean[c] = h.sum[c] / float(h.count);
  return h;
}

// The per-texel part of the model for one table: sum over texels of min_m 3m^2 + 2m(B - P).
float modifierError(const Etc1Half& h, int table, float baseGrey) {
  const int* m = kEtcModifiers[table];
  float error = 0.0f;
  for (int i = 0; i < h.count; ++i) {
    const float d = 2.0f * (baseGrey - h.grey[i]);
    float least = float(m[0]) * (3.0f * float(m[0]) + d);
    for (int k = 1; k < 4; ++k)
      least = std::min(least, float(m[k]) * (3.0f * float(m[k]) + d));
    error += least;
  }
  return error;
}

// The mean modifier the texels pick under a base of grey sum `baseGrey`.
float meanModifier(const Etc1Half& h, int table, float baseGrey) {
  const int* m = kEtcModifiers[table];
  float total = 0.0f;
  for (int i = 0; i < h.count; ++i) {
    const float d = 2.0f * (baseGrey - h.grey[i]);
    int pick = 0;
    float least = float(m[0]) * (3.0f * float(m[0]) + d);
    for (int k = 1; k < 4; ++k) {
      const float e = float(m[k]) * (3.0f * float(m[k]) + d);
      if (e < least) {
        least = e;
        pick = k;
      }
    }
    total += float(m[pick]);
  }
  return h.count > 0 ? total / float(h.count) : 0.0f;
}

// How hard the search looks: levels around each table's centre along the grey diagonal, and in
// every channel for the best `tablesSearched` tables; the individual mode on every block; and
// whether each table's centre also comes from every grouping of the texels (leastSquaresShift).
struct Etc1Effort {
  int diagonalReach, reach, tablesSearched;
  bool alwaysIndividual, everyGrouping;
};

// Whether the decoder's clamp to 0..255 can touch a base between levels `first` and `last` under
// a table (its largest modifier leaving the range), where the model above overstates the error.
bool mayClamp(Etc1Precision precision, const std::array<int, 3>& first,
              const std::array<int, 3>& last, int table) {
  const int largest = kEtcModifiers[table][1];
  for (int c = 0; c < 3; ++c) {
    if (precision.expand(first[c]) - largest < 0 || precision.expand(last[c]) + largest > 255)
      return true;
  }
  return false;
}

// The error of one base and table for a half with the decoder's clamp, texel by texel. Near
// black or white the clamp decouples the channels (a dark texel's blue held at 0 while red and
// green still fall), and the best bases there lie off the model's grey line.
float clampedError(const Etc1Half& h, Etc1Precision precision, const std::array<int, 3>& level,
                   int table) {
  // The four colours the half can decode to, then each texel's nearest.
  float paint[4][3];
  for (int k = 0; k < 4; ++k) {
    for (int c = 0; c < 3; ++c)
      paint[k][c] = float(std::clamp(precision.expand(level[c]) + kEtcModifiers[table][k], 0, 255));
  }
  // All eight lanes, the missing texels' (zero-filled) lanes masked out at the end.
  float least[8];
  for (int i = 0; i < 8; ++i)
    least[i] = std::numeric_limits<float>::max();
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i < 8; ++i) {
      float e = 0.0f;
      for (int c = 0; c < 3; ++c)
        e += (paint[k][c] - h.colour[c][i]) * (paint[k][c] - h.colour[c][i]);
      least[i] = std::min(least[i], e);
    }
  }
  float error = 0.0f;
  for (int i = 0; i < h.count; ++i)
    error += least[i];
  return error;
}

// The error of one base and table for a half: the model's where the clamp cannot touch it.
float halfError(const Etc1Half& h, Etc1Precision precision, const std::array<int, 3>& level,
                int table) {
  if (mayClamp(precision, level, level, table))
    return clampedError(h, precision, level, table);
  float error = h.sumOfSquares, grey = 0.0f;
  for (int c = 0; c < 3; ++c) {
    const float value = float(precision.expand(level[c]));
    error += float(h.count) * value * value - 2.0f * value * h.sum[c];
    grey += value;
  }
  return error + modifierError(h, table, grey);
}

// The best base within `reach` levels of `centre` (inside `box`) for one table.
Etc1HalfChoice searchTable(const Etc1Half& h, Etc1Precision precision, const Etc1LevelBox& box,
                           int table, const std::array<int, 3>& centre, int reach) {
  constexpr int kMaxReach = 2;
  std::array<int, 3> first, last;
  for (int c = 0; c < 3; ++c) {
    first[c] = std::max(box.low[c], centre[c] - reach);
    last[c] = std::min(box.high[c], centre[c] + reach);
  }
  Etc1HalfChoice best;
  best.table = table;
  if (mayClamp(precision, first, last, table)) {
    for (int r = first[0]; r <= last[0]; ++r) {
      for (int g = first[1]; g <= last[1]; ++g) {
        for (int b = first[2]; b <= last[2]; ++b) {
          const float error = clampedError(h, precision, {r, g, b}, table);
          if (error < best.error)
            best = {{r, g, b}, table, error};
        }
      }
    }
    return best;
  }
  // The model's colour part N|b|^2 - 2 b.S + Q splits by channel: each channel's term per level.
  float channelPart[3][2 * kMaxReach + 1];
  int channelValue[3][2 * kMaxReach + 1];
  for (int c = 0; c < 3; ++c) {
    for (int level = first[c]; level <= last[c]; ++level) {
      const float value = float(precision.expand(level));
      channelValue[c][level - first[c]] = precision.expand(level);
      channelPart[c][level - first[c]] = float(h.count) * value * value - 2.0f * value * h.sum[c];
    }
  }
  // The modifiers' part depends on the base only through its grey sum, which takes few values
  // over the neighbourhood: computed once per value.
  constexpr int kGreySpan = 3 * 2 * kMaxReach * 17 + 1;
  float perGrey[kGreySpan];
  const int greyFirst = channelValue[0][0] + channelValue[1][0] + channelValue[2][0];
  const int greyLast = channelValue[0][last[0] - first[0]] + channelValue[1][last[1] - first[1]] +
                       channelValue[2][last[2] - first[2]];
  std::fill(perGrey, perGrey + (greyLast - greyFirst + 1), -1.0f);
  for (int r = 0; r <= last[0] - first[0]; ++r) {
    for (int g = 0; g <= last[1] - first[1]; ++g) {
      for (int b = 0; b <= last[2] - first[2]; ++b) {
        const int grey = channelValue[0][r] + channelValue[1][g] + channelValue[2][b];
        float& modifiers = perGrey[grey - greyFirst];
        if (modifiers < 0.0f)
          modifiers = modifierError(h, table, float(grey));
        const float error =
            h.sumOfSquares + channelPart[0][r] + channelPart[1][g] + channelPart[2][b] + modifiers;
        if (error < best.error) {
          best.error = error;
          best.level = {first[0] + r, first[1] + g, first[2] + b};
        }
      }
    }
  }
  return best;
}

// The exact least-squares base over every way the texels can pick a table's modifiers, as
// squish's cluster fit does for BC1: a texel's pick rises with its grey (the sum of its
// channels), so sorted by grey the texels split into four runs, one per modifier (165 splits of
// eight texels). For a split with modifiers m_i the best unquantised base is the mean less the
// mean modifier, and its error is sum |p - mean|^2 - 2 sum m_i g_i + 3 (sum m_i^2 - (sum m_i)^2
// / N), g_i the texel's grey less the mean grey: each split costs a few sums. Returns the shift
// from the mean of the best split.
float leastSquaresShift(const Etc1Half& h, int table) {
  if (h.count == 0)
    return 0.0f;
  const int* m = kEtcModifiers[table];
  const float modifier[4] = {float(m[3]), float(m[2]), float(m[0]), float(m[1])};  // ascending
  float grey[8];
  const float meanGrey = h.mean[0] + h.mean[1] + h.mean[2];
  for (int i = 0; i < h.count; ++i)
    grey[i] = h.grey[i] - meanGrey;
  for (int i = 1; i < h.count; ++i) {  // insertion sort: at most eight values
    for (int j = i; j > 0 && grey[j - 1] > grey[j]; --j)
      std::swap(grey[j - 1], grey[j]);
  }
  float prefix[9] = {0.0f};
  for (int i = 0; i < h.count; ++i)
    prefix[i + 1] = prefix[i] + grey[i];
  const float n = float(h.count);
  float bestError = std::numeric_limits<float>::max(), bestShift = 0.0f;
  for (int c1 = 0; c1 <= h.count; ++c1) {
    for (int c2 = c1; c2 <= h.count; ++c2) {
      for (int c3 = c2; c3 <= h.count; ++c3) {
        const float count[4] = {float(c1), float(c2 - c1), float(c3 - c2), float(h.count - c3)};
        const float greys[4] = {prefix[c1], prefix[c2] - prefix[c1], prefix[c3] - prefix[c2],
                                prefix[h.count] - prefix[c3]};
        float sum = 0.0f, squares = 0.0f, along = 0.0f;
        for (int k = 0; k < 4; ++k) {
          sum += count[k] * modifier[k];
          squares += count[k] * modifier[k] * modifier[k];
          along += modifier[k] * greys[k];
        }
        // The split's error less the constant sum |p - mean|^2.
        const float error = 3.0f * (squares - sum * sum / n) - 2.0f * along;
        if (error < bestError) {
          bestError = error;
          bestShift = sum / n;
        }
      }
    }
  }
  return bestShift;
}

// Where one table's best base lies for a half: first the least-squares base for the modifiers
// the texels pick (the mean less their mean modifier, two rounds from the mean), then along the
// grey diagonal from it, up to `diagonalReach` levels: when a half's texels pick its table's
// modifiers unevenly (one bright texel on +b, the rest on -a), the rounds from the mean settle
// on picks that an offset of a few levels beats.
Etc1HalfChoice tableCentre(const Etc1Half& h, Etc1Precision precision, const Etc1LevelBox& box,
                           int table, const Etc1Effort& effort) {
  float centre[3] = {h.mean[0], h.mean[1], h.mean[2]};
  for (int round = 0; round < 2; ++round) {
    const float shift = meanModifier(h, table, centre[0] + centre[1] + centre[2]);
    for (int c = 0; c < 3; ++c)
      centre[c] = h.mean[c] - shift;
  }
  std::array<int, 3> start;
  for (int c = 0; c < 3; ++c)
    start[c] = std::clamp(precision.quantise(centre[c]), box.low[c], box.high[c]);
  Etc1HalfChoice best{start, table, halfError(h, precision, start, table)};
  if (effort.everyGrouping) {
    const float shift = leastSquaresShift(h, table);
    std::array<int, 3> level;
    for (int c = 0; c < 3; ++c)
      level[c] = std::clamp(precision.quantise(h.mean[c] - shift), box.low[c], box.high[c]);
    const float error = halfError(h, precision, level, table);
    if (error < best.error) {
      best = {level, table, error};
      start = level;
    }
  }
  for (int step = -effort.diagonalReach; step <= effort.diagonalReach; ++step) {
    std::array<int, 3> level;
    for (int c = 0; c < 3; ++c)
      level[c] = std::clamp(start[c] + step, box.low[c], box.high[c]);
    if (step == 0 || level == best.level)
      continue;
    const float error = halfError(h, precision, level, table);
    if (error < best.error)
      best = {level, table, error};
  }
  return best;
}

// Ranks the eight tables by their least-squares base alone, then searches the best
// `tablesSearched` within `reach` levels of it (inside `box`), offering each table's best base
// to `out`.
void searchHalf(const Etc1Half& h, Etc1Precision precision, const Etc1LevelBox& box,
                const Etc1Effort& effort, Etc1HalfCandidates& out) {
  const int reach = effort.reach, tablesSearched = effort.tablesSearched;
  std::array<Etc1HalfChoice, 8> atCentre;
  for (int table = 0; table < 8; ++table)
    atCentre[table] = tableCentre(h, precision, box, table, effort);
  std::array<int, 8> order = {0, 1, 2, 3, 4, 5, 6, 7};
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return atCentre[a].error < atCentre[b].error; });
  for (int rank = 0; rank < 8; ++rank) {
    const int table = order[rank];
    out.offer(rank < tablesSearched && reach > 0
                  ? searchTable(h, precision, box, table, atCentre[table].level, reach)
                  : atCentre[table]);
  }
}

// One whole block: flip, mode, the two halves' bases and tables.
struct Etc1Choice {
  bool flip = false, differential = true;
  std::array<int, 3> level[2]{};
  int table[2] = {0, 0};
  float error = std::numeric_limits<float>::max();  // the halves' errors as searched
};

bool withinStep(const std::array<int, 3>& first, const std::array<int, 3>& second) {
  for (int c = 0; c < 3; ++c) {
    const int step = second[c] - first[c];
    if (step < -4 || step > 3)
      return false;
  }
  return true;
}

void consider(Etc1Choice& best, bool flip, bool differential, const Etc1HalfChoice& first,
              const Etc1HalfChoice& second) {
  const float error = first.error + second.error;
  if (error < best.error) {
    best.flip = flip;
    best.differential = differential;
    best.level[0] = first.level;
    best.level[1] = second.level;
    best.table[0] = first.table;
    best.table[1] = second.table;
    best.error = error;
  }
}

// The best block for one flip, as searched.
Etc1Choice searchFlip(const float rgb[16][3], int validMask, bool flip, const Etc1Effort& effort) {
  const Etc1Half halves[2] = {halfOf(rgb, validMask, flip, 0), halfOf(rgb, validMask, flip, 1)};
  const Etc1Precision five{5}, four{4};
  Etc1HalfCandidates found[2];
  for (int half = 0; half < 2; ++half)
    searchHalf(halves[half], five, Etc1LevelBox{}, effort, found[half]);
  Etc1Choice best;
  for (int i = 0; i < found[0].size; ++i) {
    for (int j = 0; j < found[1].size; ++j) {
      if (withinStep(found[0].choice[i].level, found[1].choice[j].level))
        consider(best, flip, true, found[0].choice[i], found[1].choice[j]);
    }
  }
  const bool unconstrained = best.error <= found[0].choice[0].error + found[1].choice[0].error;
  if (!unconstrained) {
    // The halves' best bases lie beyond the step's reach: search each half again within the
    // reach of the other's two best.
    for (int fixed = 0; fixed < 2; ++fixed) {
      const int other = 1 - fixed;
      for (int i = 0; i < std::min(2, found[fixed].size); ++i) {
        const Etc1HalfChoice& anchor = found[fixed].choice[i];
        Etc1LevelBox box;
        for (int c = 0; c < 3; ++c) {
          // The second half's level is the first's plus -4..3.
          box.low[c] = std::max(0, fixed == 0 ? anchor.level[c] - 4 : anchor.level[c] - 3);
          box.high[c] = std::min(31, fixed == 0 ? anchor.level[c] + 3 : anchor.level[c] + 4);
        }
        Etc1HalfCandidates inside;
        searchHalf(halves[other], five, box, effort, inside);
        if (inside.size > 0) {
          if (fixed == 0)
            consider(best, flip, true, anchor, inside.choice[0]);
          else
            consider(best, flip, true, inside.choice[0], anchor);
        }
      }
    }
    // And in between: the first half's levels moved part of the way towards the second's in the
    // channels the step cannot span (the other channels free), then the second half searched
    // within the step's reach of where the first landed. A half with a bright texel and one
    // with a dark one often meet best with both bases off their own best.
    const std::array<int, 3>&from = found[0].choice[0].level, &to = found[1].choice[0].level;
    std::array<int, 3> excess;
    int most = 0;
    for (int c = 0; c < 3; ++c) {
      excess[c] = to[c] - from[c] - std::clamp(to[c] - from[c], -4, 3);
      most = std::max(most, std::abs(excess[c]));
    }
    for (int moved = 1; moved < most; ++moved) {
      Etc1LevelBox firstBox;
      for (int c = 0; c < 3; ++c) {
        if (excess[c] != 0) {
          firstBox.low[c] = firstBox.high[c] =
              from[c] + int(std::lround(float(excess[c] * moved) / float(most)));
        }
      }
      Etc1HalfCandidates first;
      searchHalf(halves[0], five, firstBox, effort, first);
      Etc1LevelBox secondBox;
      for (int c = 0; c < 3; ++c) {
        secondBox.low[c] = std::max(0, first.choice[0].level[c] - 4);
        secondBox.high[c] = std::min(31, first.choice[0].level[c] + 3);
      }
      Etc1HalfCandidates second;
      searchHalf(halves[1], five, secondBox, effort, second);
      consider(best, flip, true, first.choice[0], second.choice[0]);
    }
  }
  if (!unconstrained || effort.alwaysIndividual) {
    const Etc1LevelBox box4{{0, 0, 0}, {15, 15, 15}};
    Etc1HalfCandidates individual[2];
    for (int half = 0; half < 2; ++half)
      searchHalf(halves[half], four, box4, effort, individual[half]);
    consider(best, flip, false, individual[0].choice[0], individual[1].choice[0]);
  }
  return best;
}

// Packs a choice, each texel taking the modifier that decodes (with the decoder's clamp)
// closest to it; returns the squared error over the valid texels.
float pack(const Etc1Choice& choice, const float rgb[16][3], int validMask, std::uint8_t out[8]) {
  const Etc1Precision precision{choice.differential ? 5 : 4};
  std::uint64_t word = 0;
  for (int c = 0; c < 3; ++c) {
    if (choice.differential) {
      putBits(word, choice.level[0][c], 63 - 8 * c, 59 - 8 * c);
      putBits(word, choice.level[1][c] - choice.level[0][c], 58 - 8 * c, 56 - 8 * c);
    } else {
      putBits(word, choice.level[0][c], 63 - 8 * c, 60 - 8 * c);
      putBits(word, choice.level[1][c], 59 - 8 * c, 56 - 8 * c);
    }
  }
  putBits(word, choice.table[0], 39, 37);
  putBits(word, choice.table[1], 36, 34);
  putBits(word, choice.differential ? 1 : 0, 33, 33);
  putBits(word, choice.flip ? 1 : 0, 32, 32);
  float error = 0.0f;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const int t = y * 4 + x, half = choice.flip ? y / 2 : x / 2;
      const int* m = kEtcModifiers[choice.table[half]];
      int pick = 0;
      float least = std::numeric_limits<float>::max();
      for (int k = 0; k < 4; ++k) {
        float e = 0.0f;
        for (int c = 0; c < 3; ++c) {
          const float d =
              float(std::clamp(precision.expand(choice.level[half][c]) + m[k], 0, 255)) - rgb[t][c];
          e += d * d;
        }
        if (e < least) {
          least = e;
          pick = k;
        }
      }
      if ((validMask >> t) & 1)
        error += least;
      const int bit = x * 4 + y;
      word |= std::uint64_t(pick >> 1) << (16 + bit) | std::uint64_t(pick & 1) << bit;
    }
  }
  storeBigEndian(word, out);
  return error;
}

// `best`'s last step: each half's base a level up or down in one channel or in all three, and
// each other table, judged exactly (clamp included), kept while the error falls.
float polish(Etc1Choice& choice, const float rgb[16][3], int validMask, float error) {
  const int top = choice.differential ? 31 : 15;
  std::uint8_t scratch[8];
  const auto tryChoice = [&](const Etc1Choice& trial) {
    for (int half = 0; half < 2; ++half) {
      for (int c = 0; c < 3; ++c) {
        if (trial.level[half][c] < 0 || trial.level[half][c] > top)
          return false;
      }
    }
    if (choice.differential && !withinStep(trial.level[0], trial.level[1]))
      return false;
    const float e = pack(trial, rgb, validMask, scratch);
    if (e >= error)
      return false;
    error = e;
    choice = trial;
    return true;
  };
  for (int sweep = 0; sweep < 8; ++sweep) {
    bool improved = false;
    for (int half = 0; half < 2; ++half) {
      for (const int step : {-1, 1}) {
        for (int c = 0; c <= 3; ++c) {  // 3: all channels together
          Etc1Choice trial = choice;
          for (int k = 0; k < 3; ++k)
            trial.level[half][k] += c == 3 || c == k ? step : 0;
          improved = tryChoice(trial) || improved;
        }
      }
      for (int table = 0; table < 8; ++table) {
        Etc1Choice trial = choice;
        trial.table[half] = table;
        improved = (table != choice.table[half] && tryChoice(trial)) || improved;
      }
    }
    if (!improved)
      break;
  }
  return error;
}

}  // namespace

float encodeEtc1(const float rgb[16][3], int validMask, CompressionQuality quality,
                 std::uint8_t out[8]) {
  // fast: each table's centre a level along the diagonal; normal: three levels, then a level in
  // every channel for the three best tables; best: every grouping's centre too, four levels,
  // two in every channel for all eight, and the individual mode on every block.
  const Etc1Effort effort = quality == CompressionQuality::Fast ? Etc1Effort{1, 0, 0, false, false}
                            : quality == CompressionQuality::Normal
                                ? Etc1Effort{3, 1, 3, false, false}
                                : Etc1Effort{4, 2, 8, true, true};
  // The search's errors are partly the model's, so each flip's winner is packed and judged
  // exactly (best polishes it first).
  float winnerError = std::numeric_limits<float>::max();
  for (const bool flip : {false, true}) {
    Etc1Choice choice = searchFlip(rgb, validMask, flip, effort);
    std::uint8_t block[8];
    float error = pack(choice, rgb, validMask, block);
    if (quality == CompressionQuality::Best) {
      error = polish(choice, rgb, validMask, error);
      pack(choice, rgb, validMask, block);
    }
    if (error < winnerError) {
      winnerError = error;
      std::copy(block, block + 8, out);
    }
  }
  return winnerError;
}

}  // namespace relief::core::inline compression
