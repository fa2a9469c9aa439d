// ETC1, ETC2 and EAC blocks; see BlockCodecs.h. Bit layouts and tables from the ETC2/EAC
// definition in the OpenGL ES 3.0 specification (appendix C.1) and the Khronos Data Format
// specification, section "ETC2 Compressed Texture Image Formats". Blocks are big-endian 64-bit
// words; texel (x, y) uses index bit x * 4 + y (column-major).
#include "core/compression/BlockCodecs.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace relief::core::inline compression {
namespace {

std::uint64_t readBigEndian(const std::uint8_t* p) {
  std::uint64_t word = 0;
  for (int i = 0; i < 8; ++i)
    word = word << 8 | p[i];
  return word;
}

void writeBigEndian(std::uint64_t word, std::uint8_t* p) {
  for (int i = 7; i >= 0; --i) {
    p[i] = std::uint8_t(word & 0xff);
    word >>= 8;
  }
}

int bits(std::uint64_t word, int high, int low) {
  return int((word >> low) & ((std::uint64_t(1) << (high - low + 1)) - 1));
}

int extend4(int v) {
  return v << 4 | v;
}
int extend5(int v) {
  return v << 3 | v >> 2;
}
int extend6(int v) {
  return v << 2 | v >> 4;
}
int extend7(int v) {
  return v << 1 | v >> 6;
}
int clamp255(int v) {
  return std::clamp(v, 0, 255);
}

int texelIndex(std::uint64_t word, int x, int y) {
  const int bit = x * 4 + y;
  return int((word >> (16 + bit)) & 1) << 1 | int((word >> bit) & 1);
}

// T and H modes: each texel's 2-bit index picks one of four paint colours.
void paintTexels(std::uint64_t word, const int paint[4][3], float rgb[16][3]) {
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      for (int ch = 0; ch < 3; ++ch)
        rgb[y * 4 + x][ch] = float(paint[texelIndex(word, x, y)][ch]) / 255.0f;
    }
  }
}

}  // namespace

Etc2Mode etc2Mode(const std::uint8_t in[8]) {
  const std::uint64_t word = readBigEndian(in);
  if (!bits(word, 33, 33))
    return Etc2Mode::Individual;
  // Differential: each channel's five bits plus its signed 3-bit delta; the first channel whose
  // sum leaves 0..31 selects T (red), H (green) or planar (blue).
  const Etc2Mode overflow[3] = {Etc2Mode::T, Etc2Mode::H, Etc2Mode::Planar};
  for (int ch = 0; ch < 3; ++ch) {
    int delta = bits(word, 58 - 8 * ch, 56 - 8 * ch);
    if (delta >= 4)
      delta -= 8;
    const int second = bits(word, 63 - 8 * ch, 59 - 8 * ch) + delta;
    if (second < 0 || second > 31)
      return overflow[ch];
  }
  return Etc2Mode::Differential;
}

void decodeEtc2Rgb(const std::uint8_t in[8], float rgb[16][3]) {
  const std::uint64_t word = readBigEndian(in);
  const Etc2Mode mode = etc2Mode(in);
  if (mode == Etc2Mode::T) {
    const int c1[3] = {extend4(bits(word, 60, 59) << 2 | bits(word, 57, 56)),
                       extend4(bits(word, 55, 52)), extend4(bits(word, 51, 48))};
    const int c2[3] = {extend4(bits(word, 47, 44)), extend4(bits(word, 43, 40)),
                       extend4(bits(word, 39, 36))};
    const int d = kEtc2Distances[bits(word, 35, 34) << 1 | bits(word, 32, 32)];
    int paint[4][3];
    for (int ch = 0; ch < 3; ++ch) {
      paint[0][ch] = c1[ch];
      paint[1][ch] = clamp255(c2[ch] + d);
      paint[2][ch] = c2[ch];
      paint[3][ch] = clamp255(c2[ch] - d);
    }
    paintTexels(word, paint, rgb);
    return;
  }
  if (mode == Etc2Mode::H) {
    const int r1 = bits(word, 62, 59), g1 = bits(word, 58, 56) << 1 | bits(word, 52, 52),
              b1 = bits(word, 51, 51) << 3 | bits(word, 49, 47);
    const int r2 = bits(word, 46, 43), g2 = bits(word, 42, 39), b2 = bits(word, 38, 35);
    const int order = (r1 << 8 | g1 << 4 | b1) >= (r2 << 8 | g2 << 4 | b2) ? 1 : 0;
    const int d = kEtc2Distances[bits(word, 34, 34) << 2 | bits(word, 32, 32) << 1 | order];
    const int c1[3] = {extend4(r1), extend4(g1), extend4(b1)};
    const int c2[3] = {extend4(r2), extend4(g2), extend4(b2)};
    int paint[4][3];
    for (int ch = 0; ch < 3; ++ch) {
      paint[0][ch] = clamp255(c1[ch] + d);
      paint[1][ch] = clamp255(c1[ch] - d);
      paint[2][ch] = clamp255(c2[ch] + d);
      paint[3][ch] = clamp255(c2[ch] - d);
    }
    paintTexels(word, paint, rgb);
    return;
  }
  if (mode == Etc2Mode::Planar) {
    // Three colours (origin, horizontal, vertical) extrapolated linearly.
    const int o[3] = {
        extend6(bits(word, 62, 57)), extend7(bits(word, 56, 56) << 6 | bits(word, 54, 49)),
        extend6(bits(word, 48, 48) << 5 | bits(word, 44, 43) << 3 | bits(word, 41, 39))};
    const int h[3] = {extend6(bits(word, 38, 34) << 1 | bits(word, 32, 32)),
                      extend7(bits(word, 31, 25)), extend6(bits(word, 24, 19))};
    const int v[3] = {extend6(bits(word, 18, 13)), extend7(bits(word, 12, 6)),
                      extend6(bits(word, 5, 0))};
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 4; ++x) {
        for (int ch = 0; ch < 3; ++ch) {
          const int value = (x * (h[ch] - o[ch]) + y * (v[ch] - o[ch]) + 4 * o[ch] + 2) >> 2;
          rgb[y * 4 + x][ch] = float(clamp255(value)) / 255.0f;
        }
      }
    }
    return;
  }
  // Individual or differential: two base colours, one per half.
  int base[2][3];
  for (int ch = 0; ch < 3; ++ch) {
    if (mode == Etc2Mode::Individual) {
      base[0][ch] = extend4(bits(word, 63 - 8 * ch, 60 - 8 * ch));
      base[1][ch] = extend4(bits(word, 59 - 8 * ch, 56 - 8 * ch));
    } else {
      const int five = bits(word, 63 - 8 * ch, 59 - 8 * ch);
      int delta = bits(word, 58 - 8 * ch, 56 - 8 * ch);
      if (delta >= 4)
        delta -= 8;
      base[0][ch] = extend5(five);
      base[1][ch] = extend5(five + delta);
    }
  }
  const int table[2] = {bits(word, 39, 37), bits(word, 36, 34)};
  const bool flip = bits(word, 32, 32);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const int half = flip ? (y >= 2) : (x >= 2);
      const int modifier = kEtcModifiers[table[half]][texelIndex(word, x, y)];
      for (int ch = 0; ch < 3; ++ch)
        rgb[y * 4 + x][ch] = float(clamp255(base[half][ch] + modifier)) / 255.0f;
    }
  }
}

void decodeEacChannel(const std::uint8_t in[8], bool elevenBit, float values[16]) {
  const std::uint64_t word = readBigEndian(in);
  const int base = bits(word, 63, 56);
  const int multiplier = bits(word, 55, 52);
  const int* modifiers = kEacModifiers[bits(word, 51, 48)];
  for (int x = 0; x < 4; ++x) {
    for (int y = 0; y < 4; ++y) {
      const int index = bits(word, 47 - 3 * (x * 4 + y), 45 - 3 * (x * 4 + y));
      if (elevenBit) {
        // R11: base * 8 + 4 + modifier * multiplier * 8; a zero multiplier means 1/8.
        const int step = multiplier == 0 ? modifiers[index] : modifiers[index] * multiplier * 8;
        values[y * 4 + x] = float(std::clamp(base * 8 + 4 + step, 0, 2047)) / 2047.0f;
      } else {
        values[y * 4 + x] = float(clamp255(base + modifiers[index] * multiplier)) / 255.0f;
      }
    }
  }
}

// Each (table, multiplier, base) candidate's eight values come out sorted in this index order:
// the table's modifiers ascend as 3, 2, 1, 0, 4, 5, 6, 7, and neither a non-negative multiplier
// nor the clamp changes an order. So a texel's nearest value is the lowest value plus every step
// whose midpoint lies below the texel (no search, no table look-up, no branch).
constexpr int kEacAscending[8] = {3, 2, 1, 0, 4, 5, 6, 7};

// The search runs in fixed point on eight texels a vector (GCC's and Clang's vector extension;
// SSE2's pcmpgtw and pmaddwd on the x86-64 baseline). Targets and values are eighths of an R11
// step (0..16376) or 64ths of an alpha step (0..16320): 16-bit lanes, and sixteen squared
// differences sum within 32 unsigned bits (16 x 16376^2 < 2^32). A base moves every value of a
// (table, multiplier) by one amount, so the targets move instead and the midpoints and steps,
// set up once per (table, multiplier), serve every base the clamp leaves whole. Measured on
// 2048^2 normal maps to RG11 `normal` (with the multipliers below no longer tried), one thread:
// float texels summed in order (the compiler kept them scalar) 1.44 s on the bricks' and 1.73 s
// on a rough one, now 0.80 and 1.06 s; PSNR 63.32 -> 63.31 and 52.734 -> 52.734 dB (targets
// rounded to an eighth of a step); whole process, two threads, 1.15 -> 0.68 s.
typedef std::int16_t EacLanes __attribute__((vector_size(16)));
typedef std::int32_t EacSums __attribute__((vector_size(16)));
constexpr int kEacFixedR11 = 8, kEacFixedAlpha = 64;

// Per pair of lanes a[2i] b[2i] + a[2i+1] b[2i+1] in 32 bits (pmaddwd where there is SSE2).
EacSums pairProducts(EacLanes a, EacLanes b) {
#if defined(__SSE2__)
  return EacSums(_mm_madd_epi16(__m128i(a), __m128i(b)));
#else
  EacSums sums;
  for (int i = 0; i < 4; ++i)
    sums[i] = std::int32_t(a[2 * i]) * b[2 * i] + std::int32_t(a[2 * i + 1]) * b[2 * i + 1];
  return sums;
#endif
}

std::uint32_t laneTotal(EacSums sums) {
  return std::uint32_t(sums[0]) + std::uint32_t(sums[1]) + std::uint32_t(sums[2]) +
         std::uint32_t(sums[3]);
}

// A candidate whose first eight texels already reach 3/2 of the best error so far stops there:
// it cannot win, and a least-squares step from it rarely would. Measured on the 2048^2 bricks
// maps (tools/bench-compress): R11 15.6% above the exhaustive search against 15.5% without; a
// margin of 1 (prune whatever cannot win by itself) skipped refinements that would have: 17.7%.
constexpr std::int64_t kPruneNumerator = 3, kPruneDenominator = 2;
// Above any real error (those stay under 2^32) and safe to multiply by the margin.
constexpr std::int64_t kEacNoCandidate = std::int64_t(1) << 40;

// One (table, multiplier)'s values relative to the base's own term (base * 8 + 4 for R11, the
// base for alpha), in fixed point: the lowest, and per step k its midpoint and its size, each
// in all eight lanes. Lane 7 of `values` is the highest.
struct EacShape {
  EacLanes values;
  std::int16_t lowest, highest;
  EacLanes midpoint[7], step[7];
};

// The midpoints and steps of eight sorted values, each broadcast to every lane.
void setSteps(const std::int16_t values[8], EacLanes midpoint[7], EacLanes step[7]) {
  for (int k = 0; k < 7; ++k) {
    midpoint[k] = EacLanes{} + std::int16_t((values[k] + values[k + 1]) / 2);  // exact: even
    step[k] = EacLanes{} + std::int16_t(values[k + 1] - values[k]);
  }
}

// The search for one EAC block's base, multiplier and table: the block's targets in fixed point,
// and the best candidate so far.
class EacSearch {
 public:
  EacSearch(const float values[16], int validMask, bool elevenBit)
      : m_elevenBit(elevenBit),
        m_fixed(elevenBit ? kEacFixedR11 : kEacFixedAlpha),
        m_maxValue(m_fixed * (elevenBit ? 2047 : 255)) {
    // Texels outside the image (not in validMask) are masked out of every sum.
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (int t = 0; t < 16; ++t) {
      const float target = std::clamp(values[t], 0.0f, 1.0f) * float(m_maxValue);
      m_target[t / 8][t % 8] = std::int16_t(target + 0.5f);
      m_mask[t / 8][t % 8] = (validMask & (1 << t)) ? std::int16_t(-1) : std::int16_t(0);
      if (validMask & (1 << t)) {
        low = std::min(low, target);
        high = std::max(high, target);
      }
    }
    if (validMask == 0)
      low = high = 0.0f;
    // The range in the code's units, from which each table's multiplier and base start.
    m_low = low / float(m_fixed);
    m_high = high / float(m_fixed);
    m_validCount = std::max(1, std::popcount(unsigned(validMask)));
  }

  bool exact() const { return m_bestError == 0; }

  // One table's search: multipliers from the one the block's range asks for up to
  // `multipliersAbove` more, bases within baseReach of the one that centres the table on the
  // range, then least-squares steps from the best of those. Smaller multipliers are not tried:
  // searched two below and two above (`best` before), smaller ones won 3 blocks in 524,288 on a
  // rough normal map and none on the bricks' (2048^2, RG11), while one above won more blocks than
  // the range's own.
  void searchTable(int table, int multipliersAbove, int baseReach, int refinements) {
    const int* modifiers = kEacModifiers[table];
    const int span = modifiers[7] - modifiers[3];  // largest minus smallest modifier
    const float unit = m_elevenBit ? 8.0f : 1.0f;  // code units per base step and multiplier
    const int firstMultiplier =
        std::clamp(roundToInt((m_high - m_low) / (float(span) * unit)), m_elevenBit ? 0 : 1, 15);
    const int lastMultiplier = std::min(15, firstMultiplier + multipliersAbove);
    EacShape shape;
    for (int multiplier = firstMultiplier; multiplier <= lastMultiplier; ++multiplier) {
      setShape(modifiers, multiplier, shape);
      // Base that puts the table's middle on the range's middle.
      const float middleModifier = 0.5f * float(modifiers[7] + modifiers[3]);
      const float centre = 0.5f * (m_low + m_high) -
                           middleModifier * (multiplier == 0 ? 1.0f : float(multiplier) * unit);
      const int centreBase = roundToInt(m_elevenBit ? (centre - 4.0f) / 8.0f : centre);
      std::int64_t bestHere = kEacNoCandidate;
      int baseHere = centreBase, shiftHere = 0;
      for (int base = std::max(0, centreBase - baseReach);
           base <= std::min(255, centreBase + baseReach); ++base) {
        int shift = 0;
        const std::int64_t error = evaluate(shape, base, shift);
        consider(table, multiplier, base, error);
        if (error < bestHere) {
          bestHere = error;
          baseHere = base;
          shiftHere = shift;
        }
      }
      // Least-squares refinement: move the base by the picks' mean distance (in base steps)
      // and try there too, unless the window already covered it; again from there while that
      // improves, up to `refinements` steps.
      for (int step = 0; step < refinements; ++step) {
        const float stepsOff = float(shiftHere) / float(m_validCount * m_fixed) / unit;
        const int refined = std::clamp(baseHere - roundToInt(stepsOff), 0, 255);
        if (std::abs(refined - centreBase) <= baseReach || refined == baseHere)
          break;
        int shift = 0;
        const std::int64_t error = evaluate(shape, refined, shift);
        consider(table, multiplier, refined, error);
        if (error >= bestHere)
          break;
        bestHere = error;
        baseHere = refined;
        shiftHere = shift;
      }
    }
  }

  // The winner as the block's 64 bits, each texel's index picked as evaluate picks it.
  std::uint64_t word() const {
    EacShape shape;
    setShape(kEacModifiers[m_bestTable], m_bestMultiplier, shape);
    std::int16_t values[8];
    clampedValues(shape, m_bestBase, values);
    const int term = baseTerm(m_bestBase);
    std::uint64_t word = std::uint64_t(m_bestBase) << 56 | std::uint64_t(m_bestMultiplier) << 52 |
                         std::uint64_t(m_bestTable) << 48;
    for (int x = 0; x < 4; ++x) {
      for (int y = 0; y < 4; ++y) {
        const int target = m_target[y / 2][(y % 2) * 4 + x] - term;
        int rank = 0;
        for (int k = 0; k < 7; ++k)
          rank += target > (values[k] + values[k + 1]) / 2 ? 1 : 0;
        word |= std::uint64_t(kEacAscending[rank]) << (45 - 3 * (x * 4 + y));
      }
    }
    return word;
  }

 private:
  // Round half up; std::lround is a libm call in the hot path (3% of the search, measured).
  static int roundToInt(float value) { return int(std::floor(value + 0.5f)); }

  // The base's own term in fixed point.
  int baseTerm(int base) const { return m_fixed * (m_elevenBit ? base * 8 + 4 : base); }

  void setShape(const int* modifiers, int multiplier, EacShape& shape) const {
    std::int16_t values[8];
    for (int k = 0; k < 8; ++k) {
      const int modifier = modifiers[kEacAscending[k]];
      const int step = !m_elevenBit      ? modifier * multiplier
                       : multiplier == 0 ? modifier
                                         : modifier * multiplier * 8;
      values[k] = std::int16_t(m_fixed * step);
      shape.values[k] = values[k];
    }
    shape.lowest = values[0];
    shape.highest = values[7];
    setSteps(values, shape.midpoint, shape.step);
  }

  // A base's eight values relative to its term, clamped as the decoder clamps.
  void clampedValues(const EacShape& shape, int base, std::int16_t values[8]) const {
    const int term = baseTerm(base);
    for (int k = 0; k < 8; ++k)
      values[k] = std::int16_t(std::clamp(shape.values[k] + term, 0, m_maxValue) - term);
  }

  // The squared error of one base in fixed point, and (in `shift`) the summed distance from each
  // texel to the value it picked, which says where the least-squares base for those picks lies.
  // A candidate pruned after its first eight texels returns kEacNoCandidate.
  std::int64_t evaluate(const EacShape& shape, int base, int& shift) const {
    const int term = baseTerm(base);
    if (shape.lowest + term >= 0 && shape.highest + term <= m_maxValue)
      return evaluate(shape.lowest, shape.midpoint, shape.step, term, shift);
    // The clamp flattens some values: this base's own midpoints and steps.
    std::int16_t values[8];
    clampedValues(shape, base, values);
    EacLanes midpoint[7], step[7];
    setSteps(values, midpoint, step);
    return evaluate(values[0], midpoint, step, term, shift);
  }

  std::int64_t evaluate(std::int16_t lowest, const EacLanes midpoint[7], const EacLanes step[7],
                        int term, int& shift) const {
    EacSums squares = {}, sums = {};
    for (int half = 0; half < 2; ++half) {
      const EacLanes target = m_target[half] - std::int16_t(term);
      EacLanes value = EacLanes{} + lowest;
      for (int k = 0; k < 7; ++k)
        value += (target > midpoint[k]) & step[k];
      const EacLanes difference = (value - target) & m_mask[half];
      squares += pairProducts(difference, difference);
      sums += pairProducts(difference, EacLanes{} + std::int16_t(1));
      if (half == 0 &&
          kPruneDenominator * std::int64_t(laneTotal(squares)) >= kPruneNumerator * m_bestError)
        return kEacNoCandidate;
    }
    shift = std::int32_t(laneTotal(sums));
    return std::int64_t(laneTotal(squares));
  }

  void consider(int table, int multiplier, int base, std::int64_t error) {
    if (error < m_bestError) {
      m_bestError = error;
      m_bestBase = base;
      m_bestMultiplier = multiplier;
      m_bestTable = table;
    }
  }

  bool m_elevenBit;
  int m_fixed;     // fixed-point units per code unit
  int m_maxValue;  // the largest value, in fixed point
  // Texels 0-7 and 8-15 (row-major), in fixed point; the mask lanes are -1 for texels in the map.
  EacLanes m_target[2], m_mask[2];
  float m_low = 0.0f, m_high = 0.0f;  // the valid targets' range, in the code's units
  int m_validCount = 1;
  std::int64_t m_bestError = kEacNoCandidate;
  int m_bestBase = 0, m_bestMultiplier = 1, m_bestTable = 0;
};

void encodeEacChannel(const float values[16], int validMask, bool elevenBit,
                      CompressionQuality quality, std::uint8_t out[8]) {
  EacSearch search(values, validMask, elevenBit);
  // How far the wider search reaches above the range's multiplier and around the centred base.
  const int multipliersAbove = quality == CompressionQuality::Fast     ? 0
                               : quality == CompressionQuality::Normal ? 1
                                                                       : 2;
  const int baseReach = quality == CompressionQuality::Best ? 3 : 1;
  // Least-squares steps from the window's best base. More than one step (best): on 2048^2
  // normal maps +0.004 and +0.007 dB for no measurable time.
  const int refinements = quality == CompressionQuality::Best ? 4 : 1;
  // Every table (narrowing to the best few tables after a first pass lost 2% of normal-map
  // angle accuracy for 25% of speed, measured with tools/bench-compress). Stops once exact.
  for (int table = 0; table < 16 && !search.exact(); ++table)
    search.searchTable(table, multipliersAbove, baseReach, refinements);
  writeBigEndian(search.word(), out);
}

void encodeEtcBlock(TextureFormat format, CompressionQuality quality, const BlockTexels& texels,
                    int validMask, std::uint8_t* out) {
  const auto channel = [&texels](int ch, float values[16]) {
    for (int t = 0; t < 16; ++t)
      values[t] = texels[t][ch];
  };
  float values[16];
  if (format == TextureFormat::EacR11 || format == TextureFormat::EacRg11) {
    for (int ch = 0; ch < (format == TextureFormat::EacRg11 ? 2 : 1); ++ch) {
      channel(ch, values);
      encodeEacChannel(values, validMask, true, quality, out + 8 * ch);
    }
    return;
  }
  if (format == TextureFormat::Etc2A) {
    channel(3, values);
    encodeEacChannel(values, validMask, false, quality, out);
    out += 8;
  } else if (format != TextureFormat::Etc1 && format != TextureFormat::Etc2) {
    throwNotOfFamily("encodeEtcBlock", format);
  }
  // ETC1 colour: the individual or differential block (Etc1Encoder.cpp).
  float colour[16][3];
  for (int t = 0; t < 16; ++t) {
    for (int ch = 0; ch < 3; ++ch)
      colour[t][ch] = std::round(std::clamp(texels[t][ch], 0.0f, 1.0f) * 255.0f);
  }
  const float etc1Error = encodeEtc1(colour, validMask, quality, out);
  if (format == TextureFormat::Etc1)
    return;
  // ETC2: its planar mode, and at normal and best its T and H modes, where they beat ETC1's.
  std::uint8_t planar[8];
  const float planarError = encodeEtc2Planar(colour, validMask, planar);
  float bestError = std::min(etc1Error, planarError);
  if (planarError < etc1Error)
    std::copy(planar, planar + 8, out);
  // T and H colours are 4-bit: their quantisation alone costs about 17^2 / 12 = 24 per channel
  // and texel on average, so a block already within 24 per texel (all channels) rarely gains.
  // Skipping those saved about a quarter of the time for 0.003 dB on five photographs.
  const float validTexels = float(std::popcount(unsigned(validMask)));
  if (quality == CompressionQuality::Fast || bestError <= 24.0f * validTexels)
    return;
  std::uint8_t twoColours[8];
  if (encodeEtc2TOrH(colour, validMask, quality, twoColours) < bestError)
    std::copy(twoColours, twoColours + 8, out);
}

void decodeEtcBlock(TextureFormat format, const std::uint8_t* in, BlockTexels& texels) {
  float values[16];
  float rgb[16][3];
  if (format == TextureFormat::EacR11 || format == TextureFormat::EacRg11) {
    const int channels = format == TextureFormat::EacRg11 ? 2 : 1;
    for (int ch = 0; ch < channels; ++ch) {
      decodeEacChannel(in + 8 * ch, true, values);
      for (int t = 0; t < 16; ++t)
        texels[t][ch] = values[t];
    }
    for (int t = 0; t < 16; ++t) {
      for (int ch = channels; ch < 3; ++ch)
        texels[t][ch] = 0.0f;
      texels[t][3] = 1.0f;
    }
  } else if (format == TextureFormat::Etc2A) {
    decodeEacChannel(in, false, values);
    decodeEtc2Rgb(in + 8, rgb);
    for (int t = 0; t < 16; ++t) {
      std::copy(rgb[t], rgb[t] + 3, texels[t]);
      texels[t][3] = values[t];
    }
  } else if (format == TextureFormat::Etc1 || format == TextureFormat::Etc2) {
    decodeEtc2Rgb(in, rgb);
    for (int t = 0; t < 16; ++t) {
      std::copy(rgb[t], rgb[t] + 3, texels[t]);
      texels[t][3] = 1.0f;
    }
  } else {
    throwNotOfFamily("decodeEtcBlock", format);
  }
}

}  // namespace relief::core::inline compression
