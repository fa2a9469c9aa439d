// Image storage; see Image.h.
#include "core/image/Image.h"

#include <sys/mman.h>

#include <cassert>
#include <cstdlib>
#include <new>

namespace relief::core::inline image {

namespace {

// Rasters from this size up are aligned to and advised as huge pages (x86-64's 2 MiB).
constexpr std::size_t kHugePage = std::size_t(2) << 20;
constexpr std::size_t kHugeFrom = 4 * kHugePage;

}  // namespace

float* Image::UnsetAllocator::allocate(std::size_t count) {
  const std::size_t bytes = count * sizeof(float);
  if (bytes < kHugeFrom)
    return std::allocator<float>::allocate(count);
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* memory = std::aligned_alloc(kHugePage, rounded);
  if (!memory)
    throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
  madvise(memory, rounded, MADV_HUGEPAGE);  // advice only: a failure changes nothing
#endif
  return static_cast<float*>(memory);
}

void Image::UnsetAllocator::deallocate(float* values, std::size_t count) noexcept {
  if (count * sizeof(float) < kHugeFrom)
    std::allocator<float>::deallocate(values, count);
  else
    std::free(values);
}

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
