// Image storage; see Image.h.
#include "core/image/Image.h"

#include <cassert>

namespace relief::core::inline image {

Image::Image(int width, int height, int channels, ColorSpace colorSpace)
    : m_width(width), m_height(height), m_channels(channels), m_colorSpace(colorSpace) {
  assert(width > 0 && height > 0 && width <= kMaxImageDimension && height <= kMaxImageDimension);
  assert(channels >= 1 && channels <= 4);
  m_pixels.assign(pixelCount() * std::size_t(channels), 0.0f);
}

Image Image::forOverwrite(int width, int height, int channels, ColorSpace colorSpace) {
  assert(width > 0 && height > 0 && width <= kMaxImageDimension && height <= kMaxImageDimension);
  assert(channels >= 1 && channels <= 4);
  Image image;
  image.m_width = width;
  image.m_height = height;
  image.m_channels = channels;
  image.m_colorSpace = colorSpace;
  image.m_pixels.resize(image.pixelCount() * std::size_t(channels));
  return image;
}

bool Image::operator==(const Image& other) const {
  return m_width == other.m_width && m_height == other.m_height && m_channels == other.m_channels &&
         m_colorSpace == other.m_colorSpace && m_pixels == other.m_pixels;
}

Image channelImage(const Image& image, int channel) {
  Image result(image.width(), image.height(), 1, ColorSpace::Linear);
  result.setSourceBitsPerChannel(image.sourceBitsPerChannel());
  const std::size_t stride = std::size_t(image.channels());
  for (std::size_t p = 0; p < result.pixelCount(); ++p)
    result.data()[p] = image.data()[p * stride + std::size_t(channel)];
  return result;
}

std::optional<int> channelFromLetter(std::string_view letter) {
  constexpr std::string_view kLetters = "rgba";
  if (letter.size() != 1 || kLetters.find(letter[0]) == std::string_view::npos)
    return std::nullopt;
  return int(kLetters.find(letter[0]));
}

char channelLetter(int channel) {
  return "rgba"[channel & 3];
}

}  // namespace relief::core::inline image
