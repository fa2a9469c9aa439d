// Image: a CPU raster of 1-4 float channels with a colour-space tag. It is the currency of
// every map in Relief (loading, generation, compression, offscreen renders); values are kept
// as the file encodes them (sRGB colour stays sRGB-encoded) and never quantised on the way.
#pragma once

#include "core/base/LargeBuffer.h"
#include "core/image/ColorSpace.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

namespace relief::core::inline image {

// The largest width or height Relief accepts. 16384 is the maximum texture size of current
// desktop GPUs (and of llvmpipe); a file claiming more is refused before anything is allocated.
constexpr int kMaxImageDimension = 16384;

class Image {
 public:
  Image() = default;
  // Allocates width*height*channels floats set to zero. Sizes must already be validated
  // (1..kMaxImageDimension, 1..4 channels); violating that is a programmer error.
  Image(int width, int height, int channels, ColorSpace colorSpace = ColorSpace::Linear);
  // The same shape with the values left unset, for a caller that writes every one of them
  // before anything reads them (a decoder, a per-texel generator). Zeroing a 4096^2 RGB float
  // image first costs a serial pass over 192 MiB, a quarter of a whole `generate normal`.
  static Image forOverwrite(int width, int height, int channels,
                            ColorSpace colorSpace = ColorSpace::Linear);

  int width() const { return m_width; }
  int height() const { return m_height; }
  int channels() const { return m_channels; }
  bool isEmpty() const { return m_pixels.empty(); }
  std::size_t pixelCount() const { return std::size_t(m_width) * std::size_t(m_height); }

  ColorSpace colorSpace() const { return m_colorSpace; }
  void setColorSpace(ColorSpace space) { m_colorSpace = space; }

  // Bits per channel of the file the image came from (8, 16 or 32), or of the precision it
  // should be saved at; 0 when unknown. Saving with SampleFormat::Auto honours it.
  int sourceBitsPerChannel() const { return m_sourceBits; }
  void setSourceBitsPerChannel(int bits) { m_sourceBits = bits; }

  float* data() { return m_pixels.data(); }
  const float* data() const { return m_pixels.data(); }
  std::size_t valueCount() const { return m_pixels.size(); }

  float& at(int x, int y, int channel) { return m_pixels[index(x, y, channel)]; }
  float at(int x, int y, int channel) const { return m_pixels[index(x, y, channel)]; }
  float* pixel(int x, int y) { return &m_pixels[index(x, y, 0)]; }
  const float* pixel(int x, int y) const { return &m_pixels[index(x, y, 0)]; }

  // Pixel values and shape are equal; the colour-space tag is compared too.
  bool operator==(const Image& other) const;

 private:
  std::size_t index(int x, int y, int channel) const {
    return (std::size_t(y) * std::size_t(m_width) + std::size_t(x)) * std::size_t(m_channels) +
           std::size_t(channel);
  }

  int m_width = 0;
  int m_height = 0;
  int m_channels = 0;
  int m_sourceBits = 0;
  ColorSpace m_colorSpace = ColorSpace::Linear;
  // Unset until written (the constructor above fills with zero explicitly) and in huge pages when
  // large: LargeBuffer.h says why.
  std::vector<float, LargeBufferAllocator<float>> m_pixels;
};

// One channel of an image as a grey image of its size (linear, the source's bit depth): a
// map packed into a channel of another texture, as ORM textures hold three. `channel` must be
// below image.channels().
Image channelImage(const Image& image, int channel);
// "r", "g", "b", "a" -> 0..3; nullopt for anything else.
std::optional<int> channelFromLetter(std::string_view letter);
char channelLetter(int channel);  // 0..3 -> 'r'..'a'

}  // namespace relief::core::inline image
