// TextureCache; see TextureCache.h.
#include "renderer/TextureCache.h"

#include "core/compression/Compressor.h"
#include "core/compression/MipChain.h"
#include "core/tracing/ConeMap.h"
#include "core/tracing/MaxMipPyramid.h"
#include "renderer/CompressedUpload.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace relief::renderer {
namespace {

using core::Image;
using core::MapSlot;

// The value an empty slot samples as: mid-grey colour, a flat normal, and for data the slot's
// neutral value (core/material/MapSlot.cpp).
std::shared_ptr<const Image> neutralImage(MapSlot slot) {
  auto image = std::make_shared<Image>(1, 1, 4, core::mapSlotColorSpace(slot));
  float* texel = image->pixel(0, 0);
  switch (core::mapSlotTexels(slot)) {
    case core::MapTexels::Colour:
      std::fill(texel, texel + 3, 0.7f);
      break;
    case core::MapTexels::Normal:
      texel[0] = 0.5f;
      texel[1] = 0.5f;
      texel[2] = 1.0f;
      break;
    case core::MapTexels::Scalar:
      std::fill(texel, texel + 3, core::mapSlotNeutralValue(slot));
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
std::vector<T> pack(const Image& image, int outChannels, Convert convert) {
  std::vector<T> packed(image.pixelCount() * std::size_t(outChannels));
  for (int y = 0; y < image.height(); ++y) {
    T* row = &packed[std::size_t(y) * std::size_t(image.width()) * std::size_t(outChannels)];
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

namespace {

// Storage format of a slot's texture and the pixel layout its texels are given in.
void setSlotFormat(QOpenGLTexture& texture, MapSlot slot) {
  switch (core::mapSlotTexels(slot)) {
    case core::MapTexels::Colour:
      // Colour is sRGB-encoded; sRGB storage is exact for 8-bit sources and lets the sampler
      // filter in linear light. 16-bit colour sources lose their extra bits here.
      texture.setFormat(QOpenGLTexture::SRGB8_Alpha8);
      break;
    case core::MapTexels::Normal:
      // 16-bit unsigned normalised: exact for 8- and 16-bit files, 4x finer than 8 bits for EXR.
      texture.setFormat(QOpenGLTexture::RGBA16_UNorm);
      break;
    case core::MapTexels::Scalar:
      // Height, AO, roughness: one float channel keeps 16-bit and float files exact.
      texture.setFormat(QOpenGLTexture::R32F);
      break;
  }
}

void uploadLevel(QOpenGLTexture& texture, int level, const Image& image, MapSlot slot) {
  QOpenGLPixelTransferOptions unpack;
  unpack.setAlignment(1);
  switch (core::mapSlotTexels(slot)) {
    case core::MapTexels::Colour: {
      const auto texels = pack<std::uint8_t>(image, 4, toUnorm8);
      texture.setData(level, QOpenGLTexture::RGBA, QOpenGLTexture::UInt8, texels.data(), &unpack);
      break;
    }
    case core::MapTexels::Normal: {
      const auto texels = pack<std::uint16_t>(image, 4, toUnorm16);
      texture.setData(level, QOpenGLTexture::RGBA, QOpenGLTexture::UInt16, texels.data(), &unpack);
      break;
    }
    case core::MapTexels::Scalar: {
      // A one-channel image is already the texture's layout: uploaded without a copy, which
      // for an 8192x8192 height map saves 256 MiB at the peak.
      if (image.channels() == 1) {
        texture.setData(level, QOpenGLTexture::Red, QOpenGLTexture::Float32, image.data(), &unpack);
        break;
      }
      const auto texels = pack<float>(image, 1, [](float v) { return v; });
      texture.setData(level, QOpenGLTexture::Red, QOpenGLTexture::Float32, texels.data(), &unpack);
      break;
    }
  }
}

std::pair<QOpenGLTexture::PixelFormat, QOpenGLTexture::PixelType> transferFormat(MapSlot slot) {
  switch (core::mapSlotTexels(slot)) {
    case core::MapTexels::Colour:
      return {QOpenGLTexture::RGBA, QOpenGLTexture::UInt8};
    case core::MapTexels::Normal:
      return {QOpenGLTexture::RGBA, QOpenGLTexture::UInt16};
    case core::MapTexels::Scalar:
      return {QOpenGLTexture::Red, QOpenGLTexture::Float32};
  }
  return {QOpenGLTexture::Red, QOpenGLTexture::Float32};  // not reached
}

std::unique_ptr<QOpenGLTexture> newMapTexture(int width, int height, int levels, MapSlot slot) {
  auto texture = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
  texture->setSize(width, height);
  texture->setMipLevels(levels);
  texture->setWrapMode(QOpenGLTexture::Repeat);
  texture->setMinMagFilters(
      levels > 1 ? QOpenGLTexture::LinearMipMapLinear : QOpenGLTexture::Linear,
      QOpenGLTexture::Linear);
  setSlotFormat(*texture, slot);
  const auto [format, type] = transferFormat(slot);
  texture->allocateStorage(format, type);
  return texture;
}

}  // namespace

std::unique_ptr<QOpenGLTexture> createMapTexture(const Image& image, MapSlot slot,
                                                 const core::MipChainSpec& chain,
                                                 const Image* spreadNormals) {
  const int levels = chain.mipmaps ? core::mipLevelCount(image.width(), image.height()) : 1;
  auto texture = newMapTexture(image.width(), image.height(), levels, slot);
  uploadLevel(*texture, 0, image, slot);
  if (levels == 1)
    return texture;
  if ((chain.foldNormalSpread && slot == MapSlot::Roughness) || chain.alphaCutoff > 0.0f) {
    // A folded roughness chain or one keeping alpha coverage: all levels at once (a third of the
    // map). A fold that cannot be made (no normal map, another size) falls through to the plain
    // chain, as the export refuses it and would not ship it either.
    core::Result<std::vector<Image>> shipped =
        core::shippedMipLevels(image, slot, chain, spreadNormals);
    if (shipped) {
      for (int i = 1; i < levels; ++i)
        uploadLevel(*texture, i, shipped.value()[std::size_t(i - 1)], slot);
      return texture;
    }
  }
  // Level by level, each from the one above, keeping only the level being uploaded (an 8192^2
  // float map's chain would hold 85 MiB more at once); the levels core::shippedMipLevels makes.
  Image level;
  for (int i = 1; i < levels; ++i) {
    level = core::downsampleForSlot(i == 1 ? image : level, slot, chain.filter);
    uploadLevel(*texture, i, level, slot);
  }
  return texture;
}

std::unique_ptr<QOpenGLTexture> createDecodedTexture(const core::CompressedTexture& compressed,
                                                     MapSlot slot) {
  const int levels = int(compressed.levels.size());
  if (levels == 0)
    return nullptr;
  auto texture =
      newMapTexture(compressed.levels[0].width, compressed.levels[0].height, levels, slot);
  // Mip levels beyond the file's would be incomplete; the texture ends where the file does.
  texture->setMipMaxLevel(levels - 1);
  for (int level = 0; level < levels; ++level) {
    core::Result<Image> decoded = core::decodeAsMap(compressed, level);
    if (!decoded)
      return nullptr;
    uploadLevel(*texture, level, decoded.value(), slot);
  }
  return texture;
}

QOpenGLTexture& TextureCache::texture(const core::Material& material, MapSlot slot,
                                      const core::MipChainSpec& chain) {
  const std::shared_ptr<const Image>& image = material.map(slot).image;
  if (!image) {
    std::unique_ptr<QOpenGLTexture>& neutral = m_neutral[std::size_t(slot)];
    if (!neutral)
      neutral = createMapTexture(*neutralImage(slot), slot);
    return *neutral;
  }
  Entry& entry = m_uploads[Key{image.get(), slot}];
  // A folded roughness chain depends on the normal map as well.
  const bool folds = chain.foldNormalSpread && slot == MapSlot::Roughness && chain.mipmaps;
  const std::shared_ptr<const Image> spreadNormals =
      folds ? material.map(MapSlot::Normal).image : nullptr;
  if (entry.texture && !entry.compressed &&
      (entry.chain != chain || entry.spreadNormals != spreadNormals))
    entry.texture.reset();
  if (!entry.texture) {
    entry.chain = chain;
    entry.spreadNormals = spreadNormals;
    entry.image = image;
    if (const auto& compressed = material.map(slot).compressed) {
      entry.compressed = true;
      if (m_nativeCompressed)
        entry.texture = createCompressedTexture(*compressed);
      entry.native = entry.texture != nullptr;
      if (!entry.texture)
        entry.texture = createDecodedTexture(*compressed, slot);
    }
    if (!entry.texture)
      entry.texture = createMapTexture(*image, slot, chain, spreadNormals.get());
  }
  return *entry.texture;
}

std::optional<bool> TextureCache::uploadedNatively(const core::Material& material, MapSlot slot) {
  if (!material.map(slot).compressed)
    return std::nullopt;
  texture(material, slot);
  return m_uploads[Key{material.image(slot), slot}].native;
}

TracedHeightKey tracedHeightKey(const core::Material& material) {
  const bool packed = material.parameterFlag(core::ParamId::HeightInNormalAlpha);
  const MapSlot slot = packed ? MapSlot::Normal : MapSlot::Height;
  // An empty slot keys as null (kept while the slot stays empty) and reads the neutral texel.
  return TracedHeightKey{material.image(slot), material.map(slot).compressed.get(), packed,
                         material.parameterFlag(core::ParamId::HeightIsDepth)};
}

namespace {

// What the shader fetches as height: a compression preview's decoded texels, or the image.
std::shared_ptr<const Image> tracedTexels(
    const std::shared_ptr<const Image>& image,
    const std::shared_ptr<const core::CompressedTexture>& compressed) {
  if (compressed) {
    core::Result<Image> decoded = core::decodeAsMap(*compressed, 0);
    if (decoded)
      return std::make_shared<const Image>(std::move(decoded.value()));
  }
  return image;
}

}  // namespace

core::ConeMap buildTracedConeMap(const core::Material& material) {
  const TracedHeightKey key = tracedHeightKey(material);
  const MapSlot slot = key.packed ? MapSlot::Normal : MapSlot::Height;
  std::shared_ptr<const Image> image = material.map(slot).image;
  if (!image)
    image = neutralImage(slot);
  const std::shared_ptr<const Image> texels = tracedTexels(image, material.map(slot).compressed);
  // The cones bound the float texels; the shader allows for a 16-bit texture's rounding.
  return core::buildConeMap(*texels, key.packed ? 3 : 0, key.depth);
}

TextureCache::TraceEntry& TextureCache::traceEntry(const TracedHeightKey& key,
                                                   const core::Material& material) {
  TraceEntry& entry = m_traces[key];
  if (!entry.image) {
    const MapSlot slot = key.packed ? MapSlot::Normal : MapSlot::Height;
    entry.image = material.map(slot).image ? material.map(slot).image : neutralImage(slot);
    entry.compressed = material.map(slot).compressed;
  }
  return entry;
}

std::shared_ptr<const Image> TextureCache::TraceEntry::texels() const {
  return tracedTexels(image, compressed);
}

namespace {

// One level of floats, rows as the image stores them.
struct FloatLevel {
  int width;
  int height;
  const float* values;
};

// An R32F texture with one mip level per entry of `levels`, nearest filtering: the shaders read
// them with texelFetch.
std::unique_ptr<QOpenGLTexture> uploadFloatLevels(const std::vector<FloatLevel>& levels) {
  auto texture = std::make_unique<QOpenGLTexture>(QOpenGLTexture::Target2D);
  texture->setSize(levels[0].width, levels[0].height);
  texture->setMipLevels(int(levels.size()));
  texture->setMipMaxLevel(int(levels.size()) - 1);
  texture->setMinMagFilters(QOpenGLTexture::NearestMipMapNearest, QOpenGLTexture::Nearest);
  texture->setWrapMode(QOpenGLTexture::ClampToEdge);
  texture->setFormat(QOpenGLTexture::R32F);
  texture->allocateStorage(QOpenGLTexture::Red, QOpenGLTexture::Float32);
  QOpenGLPixelTransferOptions unpack;
  unpack.setAlignment(1);
  for (std::size_t level = 0; level < levels.size(); ++level) {
    texture->setData(int(level), QOpenGLTexture::Red, QOpenGLTexture::Float32, levels[level].values,
                     &unpack);
  }
  return texture;
}

}  // namespace

QOpenGLTexture& TextureCache::heightPyramid(const core::Material& material) {
  const TracedHeightKey key = tracedHeightKey(material);
  TraceEntry& entry = traceEntry(key, material);
  if (entry.pyramid)
    return *entry.pyramid;
  core::MaxMipPyramid pyramid =
      core::buildMaxMipPyramid(*entry.texels(), key.packed ? 3 : 0, key.depth);
  if (key.packed) {
    // The normal texture keeps 16 bits; a bound a rounding below its alpha could miss a hit.
    for (core::MaxMipLevel& level : pyramid.levels) {
      for (float& value : level.values)
        value += 1.0f / 65535.0f;
    }
  }
  std::vector<FloatLevel> levels;
  for (const core::MaxMipLevel& level : pyramid.levels)
    levels.push_back({level.width, level.height, level.values.data()});
  entry.pyramid = uploadFloatLevels(levels);
  return *entry.pyramid;
}

QOpenGLTexture& TextureCache::coneMap(const core::Material& material) {
  TraceEntry& entry = traceEntry(tracedHeightKey(material), material);
  if (!entry.cones)
    provideConeMap(material, buildTracedConeMap(material));
  return *entry.cones;
}

bool TextureCache::coneMapReady(const core::Material& material) const {
  if (!m_deferredConeMaps)
    return true;
  const auto it = m_traces.find(tracedHeightKey(material));
  return it != m_traces.end() && it->second.cones;
}

void TextureCache::provideConeMap(const core::Material& material, const core::ConeMap& cones) {
  TraceEntry& entry = traceEntry(tracedHeightKey(material), material);
  entry.cones = uploadFloatLevels({{cones.width, cones.height, cones.ratios.data()}});
}

void TextureCache::releaseUnused(std::initializer_list<const core::Material*> materials) {
  for (auto it = m_uploads.begin(); it != m_uploads.end();) {
    bool used = false;
    for (const core::Material* material : materials) {
      used = used || material->image(it->first.second) == it->first.first;
    }
    it = used ? std::next(it) : m_uploads.erase(it);
  }
  for (auto it = m_traces.begin(); it != m_traces.end();) {
    bool used = false;
    const MapSlot slot = it->first.packed ? MapSlot::Normal : MapSlot::Height;
    for (const core::Material* material : materials) {
      used = used || (material->image(slot) == it->first.image &&
                      material->map(slot).compressed.get() == it->first.compressed &&
                      material->parameterFlag(core::ParamId::HeightIsDepth) == it->first.depth);
    }
    it = used ? std::next(it) : m_traces.erase(it);
  }
}

void TextureCache::setNativeCompressedUploads(bool native) {
  if (native == m_nativeCompressed)
    return;
  m_nativeCompressed = native;
  // Compressed previews are uploaded again the other way at their next use; other maps stay.
  for (auto it = m_uploads.begin(); it != m_uploads.end();)
    it = it->second.compressed ? m_uploads.erase(it) : std::next(it);
}

void TextureCache::release() {
  m_uploads.clear();
  m_traces.clear();
  for (auto& neutral : m_neutral)
    neutral.reset();
}

}  // namespace relief::renderer
