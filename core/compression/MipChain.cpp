// MipChain; see MipChain.h. Our own filter rather than ImageBufAlgo::resize: the colour and
// normal steps need a per-texel transform around the average, and an exact area box over two
// texels is all a mip level needs.
#include "core/compression/MipChain.h"

#include "core/ColorSpace.h"

#include <algorithm>
#include <cmath>

namespace relief::core {
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

// Area box filter of a prepared (linear-valued) image.
Image boxDown(const Image& image) {
  const int width = std::max(1, image.width() / 2), height = std::max(1, image.height() / 2);
  const int channels = image.channels();
  Image out(width, height, channels, image.colorSpace());
  out.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  for (int y = 0; y < height; ++y) {
    const Footprint fy = footprint(y, image.height(), height);
    for (int x = 0; x < width; ++x) {
      const Footprint fx = footprint(x, image.width(), width);
      float* target = out.pixel(x, y);
      for (int j = 0; j < fy.count; ++j) {
        for (int i = 0; i < fx.count; ++i) {
          const float weight = fx.weights[i] * fy.weights[j];
          const float* source = image.pixel(fx.first + i, fy.first + j);
          for (int c = 0; c < channels; ++c)
            target[c] += weight * source[c];
        }
      }
    }
  }
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
  if (slot == MapSlot::Color) {
    Image linear = image;
    const int colourChannels = std::min(3, image.channels());
    for (std::size_t p = 0; p < linear.pixelCount(); ++p) {
      for (int c = 0; c < colourChannels; ++c) {
        float& v = linear.data()[p * std::size_t(image.channels()) + std::size_t(c)];
        v = srgbToLinear(v);
      }
    }
    Image down = boxDown(linear);
    for (std::size_t p = 0; p < down.pixelCount(); ++p) {
      for (int c = 0; c < colourChannels; ++c) {
        float& v = down.data()[p * std::size_t(down.channels()) + std::size_t(c)];
        v = linearToSrgb(v);
      }
    }
    return down;
  }
  if (slot == MapSlot::Normal && image.channels() >= 3) {
    // Average the unit vectors, then make the result unit length again (stored as 0.5 + 0.5 n).
    Image vectors = image;
    for (std::size_t p = 0; p < vectors.pixelCount(); ++p) {
      float* n = vectors.data() + p * std::size_t(image.channels());
      for (int c = 0; c < 3; ++c)
        n[c] = n[c] * 2.0f - 1.0f;
    }
    Image down = boxDown(vectors);
    for (std::size_t p = 0; p < down.pixelCount(); ++p) {
      float* n = down.data() + p * std::size_t(down.channels());
      const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int c = 0; c < 3; ++c) {
        const float unit = length > 1e-8f ? n[c] / length : (c == 2 ? 1.0f : 0.0f);
        n[c] = unit * 0.5f + 0.5f;
      }
    }
    return down;
  }
  return boxDown(image);
}

std::vector<Image> buildMipChain(const Image& image, MapSlot slot) {
  std::vector<Image> chain;
  chain.push_back(image);
  while (chain.back().width() > 1 || chain.back().height() > 1)
    chain.push_back(downsampleForSlot(chain.back(), slot));
  return chain;
}

}  // namespace relief::core
