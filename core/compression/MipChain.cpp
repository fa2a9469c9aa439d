// MipChain; see MipChain.h. Our own filter rather than ImageBufAlgo::resize: the colour and
// normal steps need a per-texel transform around the average, and an exact area box over two
// texels is all a mip level needs.
#include "core/compression/MipChain.h"

#include "core/base/ParallelFor.h"
#include "core/image/ColorSpace.h"

#include <algorithm>
#include <cmath>

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

}  // namespace

int mipLevelCount(int width, int height) {
  int levels = 1;
  while (width > 1 || height > 1) {
    width = std::max(1, width / 2);
    height = std::max(1, height / 2);
    ++levels;
  }
  return levels;
}

Image downsampleForSlot(const Image& image, MapSlot slot) {
  const int channels = image.channels();
  if (slot == MapSlot::Color) {
    const int colourChannels = std::min(3, channels);
    return boxDown(
        image,
        [=](const float* in, float* out) {
          for (int c = 0; c < channels; ++c)
            out[c] = c < colourChannels ? srgbToLinear(in[c]) : in[c];
        },
        [=](float* texel) {
          for (int c = 0; c < colourChannels; ++c)
            texel[c] = linearToSrgb(texel[c]);
        });
  }
  if (slot == MapSlot::Normal && channels >= 3) {
    // Average the unit vectors, then make the result unit length again (stored as 0.5 + 0.5 n).
    return boxDown(
        image,
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
  return boxDown(
      image, [=](const float* in, float* out) { std::copy(in, in + channels, out); },
      [](float*) {});
}

std::vector<Image> buildMipChain(const Image& image, MapSlot slot) {
  std::vector<Image> chain;
  chain.push_back(image);
  while (chain.back().width() > 1 || chain.back().height() > 1)
    chain.push_back(downsampleForSlot(chain.back(), slot));
  return chain;
}

}  // namespace relief::core::inline compression
