// MipChain; see MipChain.h. Our own filters rather than ImageBufAlgo::resize: the colour and
// normal steps need a per-texel transform around the average, the box is an exact area box over
// two texels, and the Kaiser filter wraps around the edges as tiled maps need (resize clamps).
#include "core/compression/MipChain.h"

#include "core/base/ParallelFor.h"
#include "core/image/ColorSpace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>

namespace relief::core::inline compression {
namespace {

// Source texels [begin, end) and their weights covering destination texel `d` when `from`
// texels shrink to `to`.
struct Footprint {
  int first;
  int count;
  float weights[3];
};

Footprint footprint(int d, int from, int to) {
  const double scale = double(from) / to;  // 2 for even sizes, a little more for odd ones
  const double begin = d * scale, end = (d + 1) * scale;
  Footprint f{int(std::floor(begin)), 0, {0, 0, 0}};
  for (int s = f.first; s < std::min(from, int(std::ceil(end))) && f.count < 3; ++s) {
    const double covered = std::min(end, double(s + 1)) - std::max(begin, double(s));
    f.weights[f.count++] = float(covered / scale);
  }
  return f;
}

// Area box filter. `decode` turns a stored texel into the values to average (linear light,
// vectors) and `encode` turns the average back; rows run on all cores, and no decoded copy of
// the level is made (a 4096^2 level is 200 MB as floats).
template <class Decode, class Encode>
Image boxDown(const Image& image, Decode decode, Encode encode) {
  const int width = std::max(1, image.width() / 2), height = std::max(1, image.height() / 2);
  const int channels = image.channels();
  Image out(width, height, channels, image.colorSpace());
  out.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  parallelFor(height, [&](int y) {
    const Footprint fy = footprint(y, image.height(), height);
    float decoded[4];
    for (int x = 0; x < width; ++x) {
      const Footprint fx = footprint(x, image.width(), width);
      float* target = out.pixel(x, y);
      for (int j = 0; j < fy.count; ++j) {
        for (int i = 0; i < fx.count; ++i) {
          const float weight = fx.weights[i] * fy.weights[j];
          decode(image.pixel(fx.first + i, fy.first + j), decoded);
          for (int c = 0; c < channels; ++c)
            target[c] += weight * decoded[c];
        }
      }
      encode(target);
    }
  });
  return out;
}

constexpr double kKaiserAlpha = 4.0;
constexpr double kKaiserWidth = 3.0;  // destination texels on each side

// The modified Bessel function of the first kind, order 0, by its series (converges fast for
// the arguments a Kaiser window with alpha 4 gives).
double besselI0(double x) {
  double sum = 1.0, term = 1.0;
  for (int k = 1; k < 30; ++k) {
    term *= (x / (2.0 * k)) * (x / (2.0 * k));
    sum += term;
  }
  return sum;
}

// Taps and weights of one destination texel along one axis, `from` texels shrinking to `to`:
// sinc(t / scale) windowed by Kaiser(t / (scale * width)), t the source offset from the
// destination texel's centre; source indices wrap.
struct KaiserTaps {
  std::vector<int> index;
  std::vector<float> weight;
};

KaiserTaps kaiserTaps(int d, int from, int to) {
  const double scale = double(from) / to;
  const double centre = (d + 0.5) * scale - 0.5;
  const double radius = kKaiserWidth * scale;
  KaiserTaps taps;
  double total = 0.0;
  for (int s = int(std::ceil(centre - radius)); s <= int(std::floor(centre + radius)); ++s) {
    const double t = (s - centre) / scale;
    const double sinc =
        std::abs(t) < 1e-9 ? 1.0 : std::sin(std::numbers::pi * t) / (std::numbers::pi * t);
    const double x = t / kKaiserWidth;
    const double window =
        besselI0(kKaiserAlpha * std::sqrt(std::max(0.0, 1.0 - x * x))) / besselI0(kKaiserAlpha);
    taps.index.push_back(((s % from) + from) % from);
    taps.weight.push_back(float(sinc * window));
    total += sinc * window;
  }
  for (float& w : taps.weight)
    w = float(w / total);
  return taps;
}

// Kaiser filter, separable: the level decoded once (linear light, vectors), filtered along
// rows then columns, encoded.
template <class Decode, class Encode>
Image kaiserDown(const Image& image, Decode decode, Encode encode) {
  const int width = std::max(1, image.width() / 2), height = std::max(1, image.height() / 2);
  const int channels = image.channels();
  Image decoded = Image::forOverwrite(image.width(), image.height(), channels);
  parallelFor(image.height(), [&](int y) {
    for (int x = 0; x < image.width(); ++x)
      decode(image.pixel(x, y), decoded.pixel(x, y));
  });
  std::vector<KaiserTaps> columnTaps, rowTaps;
  for (int x = 0; x < width; ++x)
    columnTaps.push_back(kaiserTaps(x, image.width(), width));
  for (int y = 0; y < height; ++y)
    rowTaps.push_back(kaiserTaps(y, image.height(), height));
  Image across(width, image.height(), channels);
  parallelFor(image.height(), [&](int y) {
    for (int x = 0; x < width; ++x) {
      const KaiserTaps& taps = columnTaps[std::size_t(x)];
      float* target = across.pixel(x, y);
      for (std::size_t k = 0; k < taps.index.size(); ++k) {
        const float* source = decoded.pixel(taps.index[k], y);
        for (int c = 0; c < channels; ++c)
          target[c] += taps.weight[k] * source[c];
      }
    }
  });
  Image out(width, height, channels, image.colorSpace());
  out.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  parallelFor(height, [&](int y) {
    const KaiserTaps& taps = rowTaps[std::size_t(y)];
    for (int x = 0; x < width; ++x) {
      float* target = out.pixel(x, y);
      for (std::size_t k = 0; k < taps.index.size(); ++k) {
        const float* source = across.pixel(x, taps.index[k]);
        for (int c = 0; c < channels; ++c)
          target[c] += taps.weight[k] * source[c];
      }
      encode(target);
    }
  });
  return out;
}

// srgbToLinear of an 8-bit code's value, from a table: most colour maps are 8-bit, and a pow per
// tap made the chain of a 4096x4096 colour map cost twice its upload. Other values are decoded
// exactly.
float decodeSrgb(float encoded) {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> values{};
    for (int code = 0; code < 256; ++code)
      values[std::size_t(code)] = srgbToLinear(float(code) / 255.0f);
    return values;
  }();
  const float scaled = encoded * 255.0f;
  if (scaled >= 0.0f && scaled <= 255.0f) {
    const int code = int(scaled + 0.5f);
    if (std::abs(scaled - float(code)) < 1e-3f)
      return table[std::size_t(code)];
  }
  return srgbToLinear(encoded);
}

template <class Decode, class Encode>
Image filterDown(const Image& image, MipFilter filter, Decode decode, Encode encode) {
  return filter == MipFilter::Kaiser ? kaiserDown(image, decode, encode)
                                     : boxDown(image, decode, encode);
}

}  // namespace

std::string_view mipFilterName(MipFilter filter) {
  return filter == MipFilter::Kaiser ? "kaiser" : "box";
}

std::optional<MipFilter> findMipFilter(std::string_view name) {
  for (MipFilter filter : {MipFilter::Box, MipFilter::Kaiser}) {
    if (mipFilterName(filter) == name)
      return filter;
  }
  return std::nullopt;
}

int mipLevelCount(int width, int height) {
  int levels = 1;
  while (width > 1 || height > 1) {
    width = std::max(1, width / 2);
    height = std::max(1, height / 2);
    ++levels;
  }
  return levels;
}

Image downsampleForSlot(const Image& image, MapSlot slot, MipFilter filter) {
  const int channels = image.channels();
  if (slot == MapSlot::Color) {
    const int colourChannels = std::min(3, channels);
    return filterDown(
        image, filter,
        [=](const float* in, float* out) {
          for (int c = 0; c < channels; ++c)
            out[c] = c < colourChannels ? decodeSrgb(in[c]) : in[c];
        },
        [=](float* texel) {
          for (int c = 0; c < colourChannels; ++c)
            texel[c] = linearToSrgb(std::clamp(texel[c], 0.0f, 1.0f));
        });
  }
  if (slot == MapSlot::Normal && channels >= 3) {
    // Average the unit vectors, then make the result unit length again (stored as 0.5 + 0.5 n).
    return filterDown(
        image, filter,
        [=](const float* in, float* out) {
          for (int c = 0; c < channels; ++c)
            out[c] = c < 3 ? in[c] * 2.0f - 1.0f : in[c];
        },
        [](float* n) {
          const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
          for (int c = 0; c < 3; ++c) {
            const float unit = length > 1e-8f ? n[c] / length : (c == 2 ? 1.0f : 0.0f);
            n[c] = unit * 0.5f + 0.5f;
          }
        });
  }
  return filterDown(
      image, filter, [=](const float* in, float* out) { std::copy(in, in + channels, out); },
      [](float*) {});
}

double alphaCoverage(const Image& image, float cutoff) {
  if (image.channels() < 4 || image.pixelCount() == 0)
    return 0.0;
  std::size_t covered = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x)
      covered += image.at(x, y, 3) >= cutoff ? 1 : 0;
  }
  return double(covered) / double(image.pixelCount());
}

void scaleAlphaToCoverage(Image& level, float cutoff, double coverage) {
  if (level.channels() < 4 || level.pixelCount() == 0)
    return;
  std::vector<float> alphas;
  alphas.reserve(level.pixelCount());
  for (int y = 0; y < level.height(); ++y) {
    for (int x = 0; x < level.width(); ++x)
      alphas.push_back(level.at(x, y, 3));
  }
  // The texels to keep at or above the cutoff: the `wanted` largest alphas.
  const auto wanted = std::size_t(std::lround(coverage * double(alphas.size())));
  std::sort(alphas.begin(), alphas.end(), std::greater<float>());
  float scale = 1.0f;
  if (wanted == 0) {
    // Nothing covered: bring the largest alpha just under the cutoff (if it reaches it).
    if (alphas.front() >= cutoff) {
      scale = std::nextafter(cutoff, 0.0f) / alphas.front();
      while (alphas.front() * scale >= cutoff)
        scale = std::nextafter(scale, 0.0f);
    }
  } else {
    const float threshold = alphas[std::min(wanted, alphas.size()) - 1];
    if (threshold <= 0.0f)
      return;  // fewer non-zero texels than wanted: no scale reaches the coverage
    scale = cutoff / threshold;
    while (threshold * scale < cutoff)  // rounding must not drop the threshold texel
      scale = std::nextafter(scale, 2.0f * scale);
  }
  for (int y = 0; y < level.height(); ++y) {
    for (int x = 0; x < level.width(); ++x)
      level.at(x, y, 3) = std::min(1.0f, level.at(x, y, 3) * scale);
  }
}

std::vector<Image> buildMipChain(const Image& image, MapSlot slot, MipFilter filter) {
  std::vector<Image> chain;
  chain.push_back(image);
  while (chain.back().width() > 1 || chain.back().height() > 1)
    chain.push_back(downsampleForSlot(chain.back(), slot, filter));
  return chain;
}

}  // namespace relief::core::inline compression
