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

bool Image::operator==(const Image& other) const {
  return m_width == other.m_width && m_height == other.m_height && m_channels == other.m_channels &&
         m_colorSpace == other.m_colorSpace && m_pixels == other.m_pixels;
}

}  // namespace relief::core::inline image
