// Making maps tileable; see Tileable.h.
#include "core/generators/Tileable.h"

#include "core/base/ParallelFor.h"
#include "core/generators/ImageFilters.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace relief::core::inline generators {
namespace {

// An axis whose wrap seam is within this factor of the interior's texel-to-texel difference
// already tiles: the same bar the made tiles are held to.
constexpr double kAlreadyTiles = 1.2;

// A seam is judged against the texel pairs around it, this many on each side: a mortar line or
// a ridge that happens to run along the border raises its neighbours' contrast as much as its
// own, a seam only its own.
constexpr int kSeamNeighbourhood = 4;

Image transposed(const Image& image) {
  Image out =
      Image::forOverwrite(image.height(), image.width(), image.channels(), image.colorSpace());
  out.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  const int channels = image.channels();
  parallelFor(image.height(), [&](int y) {
    for (int x = 0; x < image.width(); ++x)
      std::copy_n(image.pixel(x, y), channels, out.pixel(y, x));
  });
  return out;
}

void transposeAll(std::vector<Image>& maps) {
  for (Image& map : maps)
    map = transposed(map);
}

// Every map's channels side by side, each divided by its standard deviation and by the square
// root of the channel count of its map and of the number of maps: in a squared difference every
// channel counts by its contrast and every map weighs the same, whatever its range.
struct Features {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;

  const float* at(int x, int y) const {
    return &values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels)];
  }
};

Features featuresOf(const std::vector<Image>& maps) {
  Features features;
  features.width = maps.front().width();
  features.height = maps.front().height();
  for (const Image& map : maps)
    features.channels += map.channels();
  features.values.resize(maps.front().pixelCount() * std::size_t(features.channels));
  int offset = 0;
  for (const Image& map : maps) {
    const int channels = map.channels();
    for (int c = 0; c < channels; ++c) {
      double sum = 0.0, squares = 0.0;
      for (std::size_t p = 0; p < map.pixelCount(); ++p) {
        const double value = map.data()[p * std::size_t(channels) + std::size_t(c)];
        sum += value;
        squares += value * value;
      }
      const double count = double(map.pixelCount());
      const double variance = std::max(squares / count - (sum / count) * (sum / count), 1e-8);
      const float scale = float(1.0 / std::sqrt(variance * double(channels) * double(maps.size())));
      for (std::size_t p = 0; p < map.pixelCount(); ++p)
        features.values[p * std::size_t(features.channels) + std::size_t(offset + c)] =
            map.data()[p * std::size_t(channels) + std::size_t(c)] * scale;
    }
    offset += channels;
  }
  return features;
}

float distance2(const float* a, const float* b, int count) {
  float sum = 0.0f;
  for (int i = 0; i < count; ++i)
    sum += (a[i] - b[i]) * (a[i] - b[i]);
  return sum;
}

// Half the size, each feature the mean of a 2x2 block: the coarser levels of the search.
Features halved(const Features& features) {
  Features half;
  half.width = features.width / 2;
  half.height = features.height / 2;
  half.channels = features.channels;
  half.values.resize(std::size_t(half.width) * std::size_t(half.height) *
                     std::size_t(half.channels));
  for (int y = 0; y < half.height; ++y) {
    for (int x = 0; x < half.width; ++x) {
      float* to = &half.values[(std::size_t(y) * std::size_t(half.width) + std::size_t(x)) *
                               std::size_t(half.channels)];
      const float* a = features.at(2 * x, 2 * y);
      const float* b = features.at(2 * x + 1, 2 * y);
      const float* c = features.at(2 * x, 2 * y + 1);
      const float* d = features.at(2 * x + 1, 2 * y + 1);
      for (int i = 0; i < half.channels; ++i)
        to[i] = 0.25f * (a[i] + b[i] + c[i] + d[i]);
    }
  }
  return half;
}

// The patch laid over the wrap seam between the last and the first column: `patch` columns,
// centred on the seam; its first and last `overlap` columns are cut into the image.
struct PatchGeometry {
  int width = 0;
  int patch = 0;
  int overlap = 0;

  int destination(int k) const { return (width - patch / 2 + k) % width; }
  bool inOverlap(int k) const { return k < overlap || k >= patch - overlap; }
};

// Where a patch comes from: its first column, and (once the other axis tiles) how many rows
// its texels are taken further down, wrapping around.
struct Placement {
  int source = 0;
  int shift = 0;
  double error = 0.0;
};

// Sum of squared feature differences between the patch taken from `placement` and the texels
// it overlaps.
double overlapError(const Features& features, const PatchGeometry& geometry,
                    const Placement& placement) {
  double sum = 0.0;
  for (int y = 0; y < features.height; ++y) {
    const int from = (y + placement.shift) % features.height;
    for (int k = 0; k < geometry.patch; ++k) {
      if (!geometry.inOverlap(k))
        continue;
      sum += distance2(features.at(placement.source + k, from),
                       features.at(geometry.destination(k), y), features.channels);
    }
  }
  return sum;
}

// The placement whose patch best matches the texels it overlaps, searched coarse to fine: every
// placement on a pyramid level about 128 texels across, then the three best refined a level at
// a time (within two texels of where the coarser level put them). `shifts`: whether rows may be
// taken from further down, which is seamless only once the other axis tiles.
Placement bestPlacement(const Features& features, int patch, int overlap, bool shifts,
                        const WorkControl& control) {
  std::vector<Features> pyramid{features};
  while (std::max(pyramid.back().width, pyramid.back().height) > 160 &&
         (overlap >> pyramid.size()) >= 2 &&
         std::min(pyramid.back().width, pyramid.back().height) >= 32)
    pyramid.push_back(halved(pyramid.back()));
  const auto geometryAt = [&](std::size_t level) {
    return PatchGeometry{pyramid[level].width, patch >> level, overlap >> level};
  };
  const auto evaluate = [&](std::size_t level, std::vector<Placement>& placements) {
    const PatchGeometry geometry = geometryAt(level);
    parallelFor(
        int(placements.size()),
        [&](int i) {
          placements[std::size_t(i)].error =
              overlapError(pyramid[level], geometry, placements[std::size_t(i)]);
        },
        control);
    const std::size_t keep =
        level == 0 ? placements.size() : std::min<std::size_t>(3, placements.size());
    std::partial_sort(placements.begin(), placements.begin() + std::ptrdiff_t(keep),
                      placements.end(),
                      [](const Placement& a, const Placement& b) { return a.error < b.error; });
    placements.resize(keep);
  };

  std::size_t level = pyramid.size() - 1;
  std::vector<Placement> placements;
  {
    const Features& top = pyramid[level];
    const int sources = top.width - geometryAt(level).patch + 1;
    for (int source = 0; source < sources; ++source)
      for (int shift = 0; shift < (shifts ? top.height : 1); ++shift)
        placements.push_back({source, shift});
    evaluate(level, placements);
  }
  while (level > 0) {
    --level;
    const Features& finer = pyramid[level];
    const int sources = finer.width - geometryAt(level).patch + 1;
    std::vector<Placement> candidates;
    for (const Placement& coarse : placements) {
      for (int ds = -2; ds <= 2; ++ds) {
        for (int dy = shifts ? -2 : 0; dy <= (shifts ? 2 : 0); ++dy) {
          const int source = 2 * coarse.source + ds;
          if (source < 0 || source >= sources)
            continue;
          const int shift = ((2 * coarse.shift + dy) % finer.height + finer.height) % finer.height;
          const bool seen = std::any_of(
              candidates.begin(), candidates.end(),
              [&](const Placement& p) { return p.source == source && p.shift == shift; });
          if (!seen)
            candidates.push_back({source, shift});
        }
      }
    }
    placements = std::move(candidates);
    evaluate(level, placements);
  }
  // Of the placements that match about as well as the best (within 10%), the first whose wrap,
  // the pair of source columns in the patch's middle that becomes the tile's border, is no
  // stronger than the pairs around it (within 1.1x): a hard edge of the photo on the tile's
  // border is where mip filtering and an artist's eye look first.
  const auto pairEnergy = [&](const Placement& placement, int x) {
    double sum = 0.0;
    for (int y = 0; y < features.height; ++y) {
      const int from = (y + placement.shift) % features.height;
      sum += distance2(features.at(x - 1, from), features.at(x, from), features.channels);
    }
    return sum;
  };
  for (const Placement& placement : placements) {
    if (placement.error > placements.front().error * 1.1)
      break;
    const int x = placement.source + patch / 2;
    double around = 0.0;
    for (int d = 1; d <= kSeamNeighbourhood; ++d)
      around += pairEnergy(placement, x - d) + pairEnergy(placement, x + d);
    if (pairEnergy(placement, x) <= 1.1 * around / (2 * kSeamNeighbourhood))
      return placement;
  }
  return placements.front();
}

// The minimum-error path down an overlap (Efros and Freeman 2001): one position in [low, high]
// per row, moving at most one texel between rows, and closed: the last row's position is next to
// the first's, because the tile wraps around the other axis too. `error` holds `width` values
// per row. Exact: the dynamic programme runs once per starting position.
std::vector<int> closedSeam(const std::vector<float>& error, int width, int height, int low,
                            int high) {
  const auto run = [&](int start, std::vector<signed char>* steps) {
    std::vector<double> cost(std::size_t(width), std::numeric_limits<double>::infinity());
    std::vector<double> next(static_cast<std::size_t>(width));
    cost[std::size_t(start)] = error[std::size_t(start)];
    for (int y = 1; y < height; ++y) {
      for (int p = low; p <= high; ++p) {
        int from = p;
        for (int d = -1; d <= 1; d += 2) {
          const int q = p + d;
          if (q >= low && q <= high && cost[std::size_t(q)] < cost[std::size_t(from)])
            from = q;
        }
        next[std::size_t(p)] =
            cost[std::size_t(from)] + error[std::size_t(y) * std::size_t(width) + std::size_t(p)];
        if (steps)
          (*steps)[std::size_t(y) * std::size_t(width) + std::size_t(p)] =
              static_cast<signed char>(from - p);
      }
      std::swap(cost, next);
    }
    int end = start;
    for (int p = std::max(low, start - 1); p <= std::min(high, start + 1); ++p)
      if (cost[std::size_t(p)] < cost[std::size_t(end)])
        end = p;
    return std::pair{cost[std::size_t(end)], end};
  };
  const int starts = high - low + 1;
  std::vector<double> totals(static_cast<std::size_t>(starts));
  parallelFor(starts, [&](int i) { totals[std::size_t(i)] = run(low + i, nullptr).first; });
  const int start = low + int(std::min_element(totals.begin(), totals.end()) - totals.begin());
  std::vector<signed char> steps(std::size_t(width) * std::size_t(height), 0);
  int position = run(start, &steps).second;
  std::vector<int> seam(static_cast<std::size_t>(height));
  for (int y = height - 1; y >= 0; --y) {
    seam[std::size_t(y)] = position;
    position += steps[std::size_t(y) * std::size_t(width) + std::size_t(position)];
  }
  seam.front() = start;
  return seam;
}

// How much of the patch a texel takes, `distance` texels on the patch's side of the cut
// (negative: on the image's side), blended over `feather` texels each way.
float patchWeight(float distance, int feather) {
  if (feather <= 0)
    return distance > 0.0f ? 1.0f : 0.0f;
  const float t = std::clamp((distance + float(feather)) / float(2 * feather), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

void renormaliseNormal(float* texel) {
  float x = texel[0] * 2.0f - 1.0f, y = texel[1] * 2.0f - 1.0f, z = texel[2] * 2.0f - 1.0f;
  const float length = std::sqrt(x * x + y * y + z * z);
  if (length < 1e-6f)
    return;
  x /= length;
  y /= length;
  z /= length;
  texel[0] = x * 0.5f + 0.5f;
  texel[1] = y * 0.5f + 0.5f;
  texel[2] = z * 0.5f + 0.5f;
}

// The smooth part of a map for two-band blending: a Gaussian of `sigma` texels, computed on the
// map shrunk by a box filter to a few texels per sigma and read back bilinearly. Exact enough
// for a band split (the detail is whatever the smooth part leaves, so map = smooth + detail
// holds exactly) at a sixtieth of a full-size blur's cost with sigma 32.
class SmoothLayer {
 public:
  SmoothLayer(const Image& map, double sigma)
      : m_factor(std::max(1, int(sigma / 4.0))),
        m_small(shrunk(map, m_factor)),
        m_blurred(gaussianBlur(m_small, sigma / m_factor, EdgeMode::Clamp)) {}

  // Channel values at texel (x, y) of the full-size map, into `out`.
  void sample(int x, int y, float* out) const {
    const float u =
        std::clamp((float(x) + 0.5f) / float(m_factor) - 0.5f, 0.0f, float(m_blurred.width() - 1));
    const float v =
        std::clamp((float(y) + 0.5f) / float(m_factor) - 0.5f, 0.0f, float(m_blurred.height() - 1));
    const int x0 = int(u), y0 = int(v);
    const int x1 = std::min(x0 + 1, m_blurred.width() - 1);
    const int y1 = std::min(y0 + 1, m_blurred.height() - 1);
    const float fx = u - float(x0), fy = v - float(y0);
    const float* a = m_blurred.pixel(x0, y0);
    const float* b = m_blurred.pixel(x1, y0);
    const float* c = m_blurred.pixel(x0, y1);
    const float* d = m_blurred.pixel(x1, y1);
    for (int i = 0; i < m_blurred.channels(); ++i) {
      const float top = a[i] + (b[i] - a[i]) * fx;
      const float bottom = c[i] + (d[i] - c[i]) * fx;
      out[i] = top + (bottom - top) * fy;
    }
  }

 private:
  static Image shrunk(const Image& map, int factor) {
    if (factor == 1)
      return map;
    const int width = (map.width() + factor - 1) / factor;
    const int height = (map.height() + factor - 1) / factor;
    const int channels = map.channels();
    Image small(width, height, channels);
    parallelFor(height, [&](int y) {
      for (int x = 0; x < width; ++x) {
        float* to = small.pixel(x, y);
        int count = 0;
        for (int sy = y * factor; sy < std::min((y + 1) * factor, map.height()); ++sy) {
          for (int sx = x * factor; sx < std::min((x + 1) * factor, map.width()); ++sx) {
            const float* from = map.pixel(sx, sy);
            for (int c = 0; c < channels; ++c)
              to[c] += from[c];
            ++count;
          }
        }
        for (int c = 0; c < channels; ++c)
          to[c] /= float(count);
      }
    });
    return small;
  }

  int m_factor;
  Image m_small;
  Image m_blurred;
};

// One quilting pass: the seam between the last and first column is covered by a patch.
void quiltColumns(std::vector<Image>& maps, std::span<const TileMap> roles,
                  const TileableOptions& options, int patch, bool shifts, TileAxisReport& report,
                  const WorkControl& control) {
  const Features features = featuresOf(maps);
  PatchGeometry geometry{features.width, patch, std::max(2, patch / 3)};
  const Placement placement = bestPlacement(features, patch, geometry.overlap, shifts, control);
  const int source = placement.source;
  report.source = source;
  const auto row = [&](int y) { return (y + placement.shift) % features.height; };

  const int feather = std::min(options.feather, (geometry.overlap - 1) / 2);
  const int low = std::max(0, feather), high = geometry.overlap - 1 - low;
  const int height = features.height;
  const int overlap = geometry.overlap;
  // The overlaps' errors, patch against image, and the cut through each (squared differences,
  // as Efros and Freeman's. Kwatra et al.'s gradient-weighted cost, which prefers cuts along the
  // texture's own edges, was tried: on cobblestones it ran cuts along the stones' rims and left
  // thin slivers of mismatched rim, worse to the eye than these.)
  std::vector<float> leftError(std::size_t(overlap) * std::size_t(height));
  std::vector<float> rightError(leftError.size());
  for (int y = 0; y < height; ++y) {
    for (int j = 0; j < overlap; ++j) {
      const int k = patch - overlap + j;
      leftError[std::size_t(y) * std::size_t(overlap) + std::size_t(j)] =
          distance2(features.at(source + j, row(y)), features.at(geometry.destination(j), y),
                    features.channels);
      rightError[std::size_t(y) * std::size_t(overlap) + std::size_t(j)] =
          distance2(features.at(source + k, row(y)), features.at(geometry.destination(k), y),
                    features.channels);
    }
  }
  // Left overlap: image before the cut, patch from it on; right overlap: the other way round.
  const std::vector<int> leftCut = closedSeam(leftError, overlap, height, low, high);
  const std::vector<int> rightCut = closedSeam(rightError, overlap, height, low, high);

  // Two-band blending (Burt and Adelson 1983): the detail above a Gaussian of a quarter of the
  // overlap is joined at the cut (feathered over `feather` texels, so texture stays crisp);
  // the smooth part below it is blended over up to half the overlap on each side of the cut,
  // so a smooth map (a height field, a gradient of light) meets without a step where the cut's
  // two sides differ in level. The same weights for every map keep the set aligned.
  const int wide = std::max(feather, overlap / 2);
  const double lowSigma = std::max(1.0, overlap / 4.0);
  for (std::size_t m = 0; m < maps.size(); ++m) {
    const Image original = maps[m];
    const SmoothLayer smoothLayer(original, lowSigma);
    Image& out = maps[m];
    const int channels = original.channels();
    const bool normal = roles[m].role == TileMapRole::Normal;
    parallelFor(height, [&](int y) {
      const int left = leftCut[std::size_t(y)], right = rightCut[std::size_t(y)];
      for (int k = 0; k < patch; ++k) {
        float detail = 1.0f, smooth = 1.0f;
        if (k < overlap) {
          const float distance = float(k - left) + 0.5f;
          detail = patchWeight(distance, feather);
          smooth = patchWeight(distance, std::clamp(left, feather, wide));
        } else if (k >= patch - overlap) {
          const float distance = float(right - (k - (patch - overlap))) - 0.5f;
          detail = patchWeight(distance, feather);
          smooth = patchWeight(distance, std::clamp(overlap - right, feather, wide));
        }
        const int destination = geometry.destination(k);
        const float* from = original.pixel(source + k, row(y));
        if (detail >= 1.0f && smooth >= 1.0f) {  // the patch's core
          std::copy_n(from, channels, out.pixel(destination, y));
          continue;
        }
        const float* under = original.pixel(destination, y);
        float fromLow[4], underLow[4];
        smoothLayer.sample(source + k, row(y), fromLow);
        smoothLayer.sample(destination, y, underLow);
        float* to = out.pixel(destination, y);
        for (int c = 0; c < channels; ++c) {
          const float smoothPart = underLow[c] + (fromLow[c] - underLow[c]) * smooth;
          const float detailPart = (under[c] - underLow[c]) +
                                   ((from[c] - fromLow[c]) - (under[c] - underLow[c])) * detail;
          to[c] = smoothPart + detailPart;
        }
        if (normal && (detail < 1.0f || smooth < 1.0f))
          renormaliseNormal(to);
      }
    });
  }

  // The cuts' strength in the result: the texels either side of each cut against the pairs
  // around it in the same row, summed over the rows.
  const Features made = featuresOf(maps);
  const auto pairAt = [&](int x, int y) {  // the pair (x - 1, x), wrapping
    return distance2(made.at((x - 1 + made.width) % made.width, y), made.at(x % made.width, y),
                     made.channels);
  };
  double cutSum = 0.0, aroundSum = 0.0;
  for (int y = 0; y < height; ++y) {
    for (const int cut : {geometry.destination(leftCut[std::size_t(y)]),
                          geometry.destination(patch - overlap + rightCut[std::size_t(y)])}) {
      cutSum += pairAt(cut, y);
      for (int d = 1; d <= kSeamNeighbourhood; ++d)
        aroundSum +=
            (pairAt(cut - d + made.width, y) + pairAt(cut + d, y)) / (2.0 * kSeamNeighbourhood);
    }
  }
  report.cutRatio = cutSum / std::max(aroundSum, 1e-20);
}

// The standard normal quantile: Phi tabulated once on [-8, 8] (std::erfc) and inverted by
// search and linear interpolation, symmetric about 0.5 as the quantile is.
double inverseNormal(double fraction) {
  constexpr int kSteps = 1 << 14;
  static const std::vector<double> table = [] {
    std::vector<double> phi(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i)
      phi[std::size_t(i)] = 0.5 * std::erfc(-(-8.0 + 16.0 * i / kSteps) / std::sqrt(2.0));
    return phi;
  }();
  if (fraction > 0.5)
    return -inverseNormal(1.0 - fraction);
  const auto upper = std::upper_bound(table.begin(), table.end(), fraction);
  const int i = std::clamp(int(upper - table.begin()) - 1, 0, kSteps - 1);
  const double span = table[std::size_t(i) + 1] - table[std::size_t(i)];
  const double t = span > 0.0 ? (fraction - table[std::size_t(i)]) / span : 0.0;
  return -8.0 + 16.0 * (i + t) / kSteps;
}

// A channel's values carried to a standard normal distribution through its own histogram and
// back: the Gaussianisation of Heitz and Neyret 2018 (section 3). Values are counted on 65536
// levels between the channel's lowest and highest value (exact for 8- and 16-bit maps); each
// level that occurs goes to the quantile of its mid-rank (the texels below it plus half its
// own), so a map and its negative map to opposite values, and values between levels are
// interpolated.
class GaussianTransform {
 public:
  static constexpr int kLevels = 65536;

  GaussianTransform(const Image& image, int channel) {
    const int channels = image.channels();
    const auto value = [&](std::size_t p) {
      return image.data()[p * std::size_t(channels) + std::size_t(channel)];
    };
    m_low = std::numeric_limits<float>::max();
    m_high = std::numeric_limits<float>::lowest();
    for (std::size_t p = 0; p < image.pixelCount(); ++p) {
      m_low = std::min(m_low, value(p));
      m_high = std::max(m_high, value(p));
    }
    if (m_high <= m_low)
      m_high = m_low + 1e-6f;
    std::vector<std::uint32_t> counts(kLevels, 0);
    for (std::size_t p = 0; p < image.pixelCount(); ++p)
      ++counts[std::size_t(std::lround(position(value(p))))];
    const double total = double(image.pixelCount());
    double below = 0.0;
    m_lastAtOrBelow.resize(kLevels);
    for (int level = 0; level < kLevels; ++level) {
      if (counts[std::size_t(level)] > 0) {
        m_levels.push_back(float(level));
        m_gaussian.push_back(
            float(inverseNormal((below + 0.5 * counts[std::size_t(level)]) / total)));
        below += counts[std::size_t(level)];
      }
      m_lastAtOrBelow[std::size_t(level)] = std::max(0, int(m_levels.size()) - 1);
    }
  }

  float forward(float value) const {
    const float at = std::clamp(position(value), 0.0f, float(kLevels - 1));
    const std::size_t i = std::size_t(m_lastAtOrBelow[std::size_t(at)]);
    if (i + 1 >= m_levels.size() || at <= m_levels[i])
      return m_gaussian[i];
    const float t = (at - m_levels[i]) / (m_levels[i + 1] - m_levels[i]);
    return m_gaussian[i] + (m_gaussian[i + 1] - m_gaussian[i]) * std::min(t, 1.0f);
  }

  float inverse(float gaussian) const {
    const auto upper = std::upper_bound(m_gaussian.begin(), m_gaussian.end(), gaussian);
    const std::size_t j = std::size_t(upper - m_gaussian.begin());
    float level = 0.0f;
    if (j == 0)
      level = m_levels.front();
    else if (j >= m_levels.size())
      level = m_levels.back();
    else {
      const float t = (gaussian - m_gaussian[j - 1]) / (m_gaussian[j] - m_gaussian[j - 1]);
      level = m_levels[j - 1] + (m_levels[j] - m_levels[j - 1]) * t;
    }
    return m_low + level / float(kLevels - 1) * (m_high - m_low);
  }

 private:
  float position(float value) const {
    return (value - m_low) / (m_high - m_low) * float(kLevels - 1);
  }

  float m_low = 0.0f, m_high = 1.0f;
  std::vector<float> m_levels;    // the levels that occur, ascending
  std::vector<float> m_gaussian;  // their Gaussian values, ascending
  std::vector<int> m_lastAtOrBelow;
};

// The shift of the cross-fade's second copy: near half the width, where the photo's own column
// pair (shift - 1, shift), which becomes the tile's wrap, is as strong as the pairs around it,
// so that neither the old seam's neighbourhood nor one of the photo's hard edges ends up on the
// tile's border.
int crossFadeShift(const Features& features) {
  const int width = features.width;
  std::vector<double> pairs(static_cast<std::size_t>(width), 0.0);  // pairs[x]: (x - 1, x)
  for (int x = 1; x < width; ++x)
    for (int y = 0; y < features.height; ++y)
      pairs[std::size_t(x)] +=
          distance2(features.at(x - 1, y), features.at(x, y), features.channels);
  int best = width / 2;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int shift = 3 * width / 8; shift <= 5 * width / 8; ++shift) {
    double around = 0.0;
    for (int d = 1; d <= kSeamNeighbourhood; ++d)
      around += pairs[std::size_t(shift - d)] + pairs[std::size_t(shift + d)];
    around /= 2 * kSeamNeighbourhood;
    const double distance =
        std::abs(std::log(std::max(pairs[std::size_t(shift)], 1e-30) / std::max(around, 1e-30)));
    if (distance < bestDistance - 1e-9) {
      bestDistance = distance;
      best = shift;
    }
  }
  return best;
}

// One cross-fade pass over columns: each texel is blended with the one `shift` columns on, with
// weights that fall to 0 at each copy's own wrap seam (the photo's at x = 0, the shifted copy's
// at x = width - shift) in proportion to the distance from it, and the variance-preserving
// normalisation of Heitz and Neyret 2018 (eq. 6): the values are zero-mean (Gaussianised data,
// or normals' slopes less their mean).
void crossFadeColumns(std::vector<Image>& zeroMean, int shift, const WorkControl& control) {
  for (Image& map : zeroMean) {
    const Image original = map;
    const int width = map.width(), channels = map.channels();
    const auto seamDistance = [&](float x, float seam) {
      const float d = std::abs(x - seam);
      return std::min(d, float(width) - d);
    };
    parallelFor(
        map.height(),
        [&](int y) {
          for (int x = 0; x < width; ++x) {
            const float centre = float(x) + 0.5f;
            const float toFirstSeam = seamDistance(centre, 0.0f);
            const float toShiftedSeam = seamDistance(centre, float(width - shift));
            const float a = toFirstSeam / (toFirstSeam + toShiftedSeam);
            const float b = 1.0f - a;
            const float norm = 1.0f / std::sqrt(a * a + b * b);
            const float* first = original.pixel(x, y);
            const float* shifted = original.pixel((x + shift) % width, y);
            float* to = map.pixel(x, y);
            for (int c = 0; c < channels; ++c)
              to[c] = (a * first[c] + b * shifted[c]) * norm;
          }
        },
        control);
  }
}

// The maps in a zero-mean blending space: data channels Gaussianised through their histograms,
// normal maps as their slopes (x, y) less the mean slope, plus any further channel (a packed
// height) Gaussianised. `back` undoes it.
struct BlendSpace {
  std::vector<Image> values;
  std::vector<std::vector<GaussianTransform>> transforms;  // per map, per Gaussianised channel
  std::vector<std::pair<float, float>> meanSlopes;         // per normal map

  BlendSpace(const std::vector<Image>& maps, std::span<const TileMap> roles) {
    for (std::size_t m = 0; m < maps.size(); ++m) {
      const Image& map = maps[m];
      const bool normal = roles[m].role == TileMapRole::Normal;
      Image blend = Image::forOverwrite(map.width(), map.height(), map.channels());
      std::vector<GaussianTransform> channels;
      const int first = normal ? 3 : 0;
      for (int c = first; c < map.channels(); ++c)
        channels.emplace_back(map, c);
      float meanX = 0.0f, meanY = 0.0f;
      if (normal) {
        double sumX = 0.0, sumY = 0.0;
        for (std::size_t p = 0; p < map.pixelCount(); ++p) {
          sumX += map.data()[p * std::size_t(map.channels())] * 2.0 - 1.0;
          sumY += map.data()[p * std::size_t(map.channels()) + 1] * 2.0 - 1.0;
        }
        meanX = float(sumX / double(map.pixelCount()));
        meanY = float(sumY / double(map.pixelCount()));
      }
      parallelFor(map.height(), [&](int y) {
        for (int x = 0; x < map.width(); ++x) {
          const float* from = map.pixel(x, y);
          float* to = blend.pixel(x, y);
          if (normal) {
            to[0] = from[0] * 2.0f - 1.0f - meanX;
            to[1] = from[1] * 2.0f - 1.0f - meanY;
            to[2] = 0.0f;
          }
          for (int c = first; c < map.channels(); ++c)
            to[c] = channels[std::size_t(c - first)].forward(from[c]);
        }
      });
      values.push_back(std::move(blend));
      transforms.push_back(std::move(channels));
      meanSlopes.emplace_back(meanX, meanY);
    }
  }

  void back(std::vector<Image>& maps, std::span<const TileMap> roles) const {
    for (std::size_t m = 0; m < maps.size(); ++m) {
      Image& map = maps[m];
      const bool normal = roles[m].role == TileMapRole::Normal;
      const int first = normal ? 3 : 0;
      parallelFor(map.height(), [&](int y) {
        for (int x = 0; x < map.width(); ++x) {
          const float* from = values[m].pixel(x, y);
          float* to = map.pixel(x, y);
          if (normal) {
            float nx = from[0] + meanSlopes[m].first, ny = from[1] + meanSlopes[m].second;
            const float slope2 = nx * nx + ny * ny;
            if (slope2 > 0.998f) {  // keep the normal above the surface
              const float shrink = std::sqrt(0.998f / slope2);
              nx *= shrink;
              ny *= shrink;
            }
            const float nz = std::sqrt(std::max(0.0f, 1.0f - nx * nx - ny * ny));
            to[0] = nx * 0.5f + 0.5f;
            to[1] = ny * 0.5f + 0.5f;
            to[2] = nz * 0.5f + 0.5f;
          }
          for (int c = first; c < map.channels(); ++c)
            to[c] = transforms[m][std::size_t(c - first)].inverse(from[c]);
        }
      });
    }
  }
};

Status validate(std::span<const TileMap> maps, const TileableOptions& options) {
  if (maps.empty())
    return Error{"make tileable: no maps given"};
  const Image& first = *maps.front().image;
  for (const TileMap& map : maps) {
    if (!map.image || map.image->isEmpty())
      return Error{"make tileable: an empty map"};
    if (map.image->width() != first.width() || map.image->height() != first.height())
      return Error{"make tileable: the maps differ in size (" + std::to_string(first.width()) +
                   "x" + std::to_string(first.height()) + " and " +
                   std::to_string(map.image->width()) + "x" + std::to_string(map.image->height()) +
                   "); a set's maps must be aligned texel for texel"};
    if (map.role == TileMapRole::Normal && map.image->channels() < 3)
      return Error{"make tileable: a normal map needs three channels (x, y, z); this one has " +
                   std::to_string(map.image->channels())};
  }
  const int shorter = std::min(first.width(), first.height());
  if (shorter < 16)
    return Error{"make tileable: " + std::to_string(first.width()) + "x" +
                 std::to_string(first.height()) + " is too small to tile (16 texels at least)"};
  if (options.method == TileMethod::Quilt && (options.patch < 0 || options.patch > shorter / 2))
    return Error{"make tileable: a patch of " + std::to_string(options.patch) +
                 " texels does not fit: at most half the image's shorter side (" +
                 std::to_string(shorter / 2) + ")"};
  if (options.method == TileMethod::Quilt && options.patch != 0 && options.patch < 8)
    return Error{"make tileable: a patch of " + std::to_string(options.patch) +
                 " texels is too narrow to cut in (8 at least)"};
  return Status::success();
}

bool axisTiles(const std::vector<Image>& maps, bool vertical) {
  return std::all_of(maps.begin(), maps.end(), [&](const Image& map) {
    return wrapSeamRatio(map, vertical) <= kAlreadyTiles;
  });
}

}  // namespace

double wrapSeamRatio(const Image& image, bool vertical) {
  const int width = image.width(), height = image.height(), channels = image.channels();
  const int along = vertical ? height : width;
  if (along < 2)
    return 1.0;
  const auto texel = [&](int i, int j) { return vertical ? image.pixel(j, i) : image.pixel(i, j); };
  const int across = vertical ? width : height;
  // pair[i]: the energy between texel i and i + 1 (the last one wrapping to 0), over the rows.
  std::vector<double> pair(static_cast<std::size_t>(along), 0.0);
  for (int j = 0; j < across; ++j)
    for (int i = 0; i < along; ++i)
      pair[std::size_t(i)] += distance2(texel(i, j), texel((i + 1) % along, j), channels);
  const double wrap = pair.back();
  double interior = 0.0;
  int count = 0;
  for (int d = 1; d <= kSeamNeighbourhood && 2 * d < along; ++d) {
    interior += pair[std::size_t(along - 1 - d)] + pair[std::size_t(d - 1)];
    count += 2;
  }
  interior /= std::max(count, 1);
  if (interior <= 1e-20)
    return wrap <= 1e-20 ? 1.0 : std::numeric_limits<double>::infinity();
  return wrap / interior;
}

Result<TileableResult> makeTileable(std::span<const TileMap> maps, const TileableOptions& options,
                                    const WorkControl& control) {
  if (Status valid = validate(maps, options); !valid)
    return Error{valid.error()};
  TileableResult result;
  for (const TileMap& map : maps)
    result.maps.push_back(*map.image);
  std::vector<Image>& out = result.maps;
  const int shorter = std::min(out.front().width(), out.front().height());
  const int patch = (options.patch > 0 ? options.patch : shorter / 3) & ~1;

  const bool doColumns = options.recut || !axisTiles(out, false);
  const bool doRows = options.recut || !axisTiles(out, true);
  result.horizontal.alreadyTiled = !doColumns;
  result.vertical.alreadyTiled = !doRows;
  result.horizontal.seamBefore = wrapSeamRatio(out.front(), false);
  result.vertical.seamBefore = wrapSeamRatio(out.front(), true);

  const auto stopped = [&] { return control.cancelled(); };
  if (options.method == TileMethod::Quilt) {
    if (doColumns)
      quiltColumns(out, maps, options, patch, !doRows, result.horizontal, control);
    control.report(0.5);
    if (stopped())
      return Error{"make tileable: cancelled"};
    if (doRows) {
      transposeAll(out);
      quiltColumns(out, maps, options, patch, true, result.vertical, control);
      transposeAll(out);
    }
  } else if (doColumns || doRows) {
    BlendSpace space(out, maps);
    if (doColumns) {
      result.horizontal.source = crossFadeShift(featuresOf(out));
      crossFadeColumns(space.values, result.horizontal.source, control);
    }
    control.report(0.4);
    if (stopped())
      return Error{"make tileable: cancelled"};
    if (doRows) {
      transposeAll(space.values);
      std::vector<Image> rows = out;
      transposeAll(rows);
      result.vertical.source = crossFadeShift(featuresOf(rows));
      crossFadeColumns(space.values, result.vertical.source, control);
      transposeAll(space.values);
    }
    control.report(0.8);
    space.back(out, maps);
  }
  if (stopped())
    return Error{"make tileable: cancelled"};
  result.horizontal.seamAfter = wrapSeamRatio(out.front(), false);
  result.vertical.seamAfter = wrapSeamRatio(out.front(), true);
  control.report(1.0);
  return result;
}

}  // namespace relief::core::inline generators
