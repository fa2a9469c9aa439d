// TextureCache; see TextureCache.h.
#include "renderer/TextureCache.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace relief::renderer {
namespace {

using core::Image;
using core::MapSlot;

// The value an empty slot samples as: mid-grey colour, a flat normal, the top surface,
// no occlusion, no roughness.
std::shared_ptr<const Image> neutralImage(MapSlot slot) {
  auto image = std::make_shared<Image>(1, 1, 4, core::mapSlotColorSpace(slot));
  float* texel = image->pixel(0, 0);
  const float colorGrey = 0.7f;
  switch (slot) {
    case MapSlot::Color:
      std::fill(texel, texel + 3, colorGrey);
      break;
    case MapSlot::Normal:
      texel[0] = 0.5f;
      texel[1] = 0.5f;
      texel[2] = 1.0f;
      break;
    case MapSlot::Height:
    case MapSlot::AmbientOcclusion:
      std::fill(texel, texel + 3, 1.0f);
      break;
    default:
      break;
  }
  texel[3] = 1.0f;
  return image;
}

// Source channel for each of the RGBA outputs: grey images spread to RGB, missing alpha is 1.
float channelValue(const float* pixel, int channels, int c) {
  if (channels >= 3)
    return c < channels ? pixel[c] : 1.0f;
  if (channels == 2)
    return c < 3 ? pixel[0] : pixel[1];
  return c < 3 ? pixel[0] : 1.0f;
}

template <class T, class Convert>
std::vector<T> packFlipped(const Image& image, int outChannels, Convert convert) {
  std::vector<T> packed(image.pixelCount() * std::size_t(outChannels));
  for (int y = 0; y < image.height(); ++y) {
    T* row = &packed[std::size_t(image.height() - 1 - y) * std::size_t(image.width()) *
                     std::size_t(outChannels)];
    for (int x = 0; x < image.width(); ++x) {
      const float* pixel = image.pixel(x, y);
      for (int c = 0; c < outChannels; ++c) {
        row[std::size_t(x) * std::size_t(outChannels) + std::size_t(c)] =
            convert(channelValue(pixel, image.channels(), c));
      }
    }
  }
  return packed;
}

std::uint8_t toUnorm8(float v) {
  return std::uint8_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}
std::uint16_t toUnorm16(float v) {
  return std::uint16_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f));
}

}  // namespace

std::unique_ptr<QOpenGLTexture> createMapTexture(const Image& image, MapSlot slot) {
  auto texture = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
  texture->setSize(image.width(), image.height());
  texture->setMipLevels(texture->maximumMipLevels());
  texture->setWrapMode(QOpenGLTexture::Repeat);
  texture->setMinMagFilters(QOpenGLTexture::LinearMipMapLinear, QOpenGLTexture::Linear);
  QOpenGLPixelTransferOptions unpack;
  unpack.setAlignment(1);

  switch (slot) {
    case MapSlot::Color: {
      // Colour is sRGB-encoded; sRGB storage is exact for 8-bit sources and lets the sampler
      // filter in linear light. 16-bit colour sources lose their extra bits here.
      const auto texels = packFlipped<std::uint8_t>(image, 4, toUnorm8);
      texture->setFormat(QOpenGLTexture::SRGB8_Alpha8);
      texture->allocateStorage(QOpenGLTexture::RGBA, QOpenGLTexture::UInt8);
      texture->setData(0, QOpenGLTexture::RGBA, QOpenGLTexture::UInt8, texels.data(), &unpack);
      break;
    }
    case MapSlot::Normal: {
      // 16-bit unsigned normalised: exact for 8- and 16-bit files, 4x finer than 8 bits for EXR.
      const auto texels = packFlipped<std::uint16_t>(image, 4, toUnorm16);
      texture->setFormat(QOpenGLTexture::RGBA16_UNorm);
      texture->allocateStorage(QOpenGLTexture::RGBA, QOpenGLTexture::UInt16);
      texture->setData(0, QOpenGLTexture::RGBA, QOpenGLTexture::UInt16, texels.data(), &unpack);
      break;
    }
    default: {
      // Height, AO, roughness: one float channel keeps 16-bit and float files exact.
      const auto texels = packFlipped<float>(image, 1, [](float v) { return v; });
      texture->setFormat(QOpenGLTexture::R32F);
      texture->allocateStorage(QOpenGLTexture::Red, QOpenGLTexture::Float32);
      texture->setData(0, QOpenGLTexture::Red, QOpenGLTexture::Float32, texels.data(), &unpack);
      break;
    }
  }
  texture->generateMipMaps();
  return texture;
}

QOpenGLTexture& TextureCache::texture(const core::Material& material, MapSlot slot) {
  const std::shared_ptr<const Image>& image = material.map(slot).image;
  if (!image) {
    std::unique_ptr<QOpenGLTexture>& neutral = m_neutral[std::size_t(slot)];
    if (!neutral)
      neutral = createMapTexture(*neutralImage(slot), slot);
    return *neutral;
  }
  Entry& entry = m_uploads[Key{image.get(), slot}];
  if (!entry.texture) {
    entry.image = image;
    entry.texture = createMapTexture(*image, slot);
  }
  return *entry.texture;
}

void TextureCache::releaseUnused(std::initializer_list<const core::Material*> materials) {
  for (auto it = m_uploads.begin(); it != m_uploads.end();) {
    bool used = false;
    for (const core::Material* material : materials) {
      used = used || material->image(it->first.second) == it->first.first;
    }
    it = used ? std::next(it) : m_uploads.erase(it);
  }
}

void TextureCache::release() {
  m_uploads.clear();
  for (auto& neutral : m_neutral)
    neutral.reset();
}

}  // namespace relief::renderer
