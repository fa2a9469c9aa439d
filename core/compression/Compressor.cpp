// Compressor; see Compressor.h.
#include "core/compression/Compressor.h"

#include "core/base/ParallelFor.h"
#include "core/compression/AstcCodec.h"
#include "core/compression/BlockCodecs.h"
#include "core/compression/BlockRdo.h"
#include "core/compression/MipChain.h"
#include "core/compression/RoughnessFold.h"
#include "core/image/HalfFloat.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

namespace relief::core::inline compression {
namespace {

// One texel of the map as four channels in the layout the format's encoder expects.
void prepareTexel(const float* in, int channels, bool twoChannelNormal, float* out) {
  if (channels >= 3) {
    out[0] = in[0];
    out[1] = in[1];
    out[2] = in[2];
  } else {
    out[0] = out[1] = out[2] = in[0];
  }
  out[3] = channels == 4 ? in[3] : channels == 2 ? in[1] : 1.0f;
  if (twoChannelNormal) {
    out[2] = 0.0f;  // rebuilt from X and Y when decoded
    out[3] = 1.0f;
  }
}

bool isTwoChannelNormal(MapSlot slot, TextureFormat format) {
  const FormatLayout layout = textureFormatInfo(format).layout;
  return slot == MapSlot::Normal &&
         (layout == FormatLayout::NormalRg || layout == FormatLayout::NormalAg);
}

// The whole map prepared, for astcenc (which takes whole images).
Image prepare(const Image& map, MapSlot slot, TextureFormat format) {
  const bool twoChannelNormal = isTwoChannelNormal(slot, format);
  Image rgba(map.width(), map.height(), 4, map.colorSpace());
  for (std::size_t p = 0; p < map.pixelCount(); ++p) {
    prepareTexel(map.data() + p * std::size_t(map.channels()), map.channels(), twoChannelNormal,
                 rgba.data() + p * 4);
  }
  return rgba;
}

// Encodes one level with the block codecs, on all cores. Texels are prepared block by block
// (no full-size copy of a large map).
bool encodeBlocks(const Image& map, MapSlot slot, const CompressionSettings& settings,
                  std::vector<std::uint8_t>& out, const WorkControl& control) {
  const TextureFormatInfo& info = textureFormatInfo(settings.format);
  const int width = map.width(), height = map.height();
  const int blocksX = (width + 3) / 4, blocksY = (height + 3) / 4;
  const bool twoChannelNormal = isTwoChannelNormal(slot, settings.format);
  const bool perceptual = settings.perceptual && slot == MapSlot::Color;
  out.assign(std::size_t(blocksX) * std::size_t(blocksY) * std::size_t(info.bytesPerBlock), 0);
  const BlockSource gather = [&](int bx, int by, BlockTexels& texels, int& validMask) {
    validMask = 0;
    for (int j = 0; j < 4; ++j) {
      for (int i = 0; i < 4; ++i) {
        const int x = bx * 4 + i, y = by * 4 + j;
        if (x < width && y < height)
          validMask |= 1 << (j * 4 + i);
        // Padding repeats the edge, so even a fit that saw these texels stays close.
        prepareTexel(map.pixel(std::min(x, width - 1), std::min(y, height - 1)), map.channels(),
                     twoChannelNormal, texels[j * 4 + i]);
      }
    }
  };
  const bool encoded = parallelFor(
      blocksY,
      [&](int by) {
        BlockTexels texels;
        for (int bx = 0; bx < blocksX; ++bx) {
          int validMask = 0;
          gather(bx, by, texels, validMask);
          std::uint8_t* block =
              out.data() + (std::size_t(by) * std::size_t(blocksX) + std::size_t(bx)) *
                               std::size_t(info.bytesPerBlock);
          if (isBcFamily(settings.format)) {
            encodeBcBlock(settings.format, settings.quality, perceptual, texels, validMask, block);
          } else {
            encodeEtcBlock(settings.format, settings.quality, texels, validMask, block);
          }
        }
      },
      control);
  if (encoded && settings.rdoLambda > 0.0f && !control.cancelled())
    reduceBlockEntropy(settings.format, settings.rdoLambda, blocksX, blocksY, gather, out);
  return encoded && !control.cancelled();
}

// A sub-range [begin, begin + share) of the overall progress.
WorkControl slice(const WorkControl& control, double begin, double share) {
  WorkControl part;
  part.cancel = control.cancel;
  if (control.progress) {
    part.progress = [progress = control.progress, begin, share](double fraction) {
      progress(begin + share * fraction);
    };
  }
  return part;
}

}  // namespace

std::uint64_t compressedLevelSize(TextureFormat format, int width, int height) {
  const TextureFormatInfo& info = textureFormatInfo(format);
  const std::uint64_t blocksX = (std::uint64_t(width) + info.blockWidth - 1) / info.blockWidth;
  const std::uint64_t blocksY = (std::uint64_t(height) + info.blockHeight - 1) / info.blockHeight;
  return blocksX * blocksY * std::uint64_t(info.bytesPerBlock);
}

std::uint64_t CompressedTexture::byteSize() const {
  std::uint64_t total = 0;
  for (const CompressedLevel& level : levels)
    total += level.data.size();
  return total;
}

bool formatSuitsSlot(TextureFormat format, MapSlot slot) {
  const FormatLayout layout = textureFormatInfo(format).layout;
  switch (mapSlotTexels(slot)) {
    case MapTexels::Colour:  // half floats: linear HDR colour (formatMapProblem refuses sRGB)
      return layout == FormatLayout::Rgb || layout == FormatLayout::Rgba ||
             layout == FormatLayout::RgbHalf;
    case MapTexels::Normal:
      return layout != FormatLayout::R && layout != FormatLayout::RgbHalf;
    case MapTexels::Scalar:
      // Half floats hold float heights and other float data beyond 8 bits' steps.
      return layout == FormatLayout::R || layout == FormatLayout::Rgb ||
             layout == FormatLayout::RgbHalf || (isAstc(format) && layout == FormatLayout::Rgba);
  }
  return false;  // not reached: every kind is handled above
}

std::vector<TextureFormat> formatsForSlot(MapSlot slot) {
  std::vector<TextureFormat> formats;
  for (const TextureFormatInfo& info : allTextureFormats()) {
    if (formatSuitsSlot(info.format, slot) && !isHalfFloatFormat(info.format))
      formats.push_back(info.format);
  }
  return formats;
}

std::vector<TextureFormat> formatsForMap(const Image& map, MapSlot slot) {
  std::vector<TextureFormat> formats = formatsForSlot(slot);
  if (map.sourceBitsPerChannel() < 16 || map.colorSpace() == ColorSpace::Srgb)
    return formats;
  for (const TextureFormatInfo& info : allTextureFormats()) {
    if (isHalfFloatFormat(info.format) && formatSuitsSlot(info.format, slot))
      formats.push_back(info.format);
  }
  return formats;
}

double shareOutsideUnitRange(const Image& map) {
  // Row by row on the pool: the scan reads the whole map from memory after the encoders have
  // left the cache (16 ms for a 2048x2048 RGB map on one thread, on the CLI's critical path).
  const std::size_t rowValues = std::size_t(map.width()) * std::size_t(map.channels());
  std::atomic<std::size_t> outside{0};
  parallelFor(map.height(), [&](int y) {
    const float* row = map.pixel(0, y);
    std::size_t count = 0;
    for (std::size_t i = 0; i < rowValues; ++i)
      count += (row[i] < 0.0f || row[i] > 1.0f) ? 1 : 0;
    outside += count;
  });
  return map.valueCount() ? double(outside) / double(map.valueCount()) : 0.0;
}

HalfFloatClamps countHalfFloatClamps(const Image& map, bool signedFormat) {
  HalfFloatClamps clamps;
  const float* values = map.data();
  for (std::size_t i = 0; i < map.valueCount(); ++i) {
    const float value = values[i];
    if (std::isnan(value))
      ++clamps.notANumber;
    else if (std::isinf(value))
      ++clamps.infinite;
    else if (std::abs(value) > kMaxHalf)
      ++clamps.beyondHalf;
    else if (!signedFormat && value < 0.0f)
      ++clamps.negative;
  }
  return clamps;
}

std::string describeHalfFloatClamps(const HalfFloatClamps& clamps, TextureFormat format) {
  std::string text;
  const auto add = [&text](std::size_t count, const std::string& what) {
    if (count == 0)
      return;
    text += (text.empty() ? "" : "; ") + std::to_string(count) + " " + what;
  };
  add(clamps.notANumber, "values are not numbers and become 0");
  add(clamps.infinite, "values are infinite and become the largest half (65504)");
  add(clamps.beyondHalf, "values lie beyond the largest half and become 65504");
  add(clamps.negative, "values are negative and become 0 (" +
                           std::string(textureFormatInfo(format).label) +
                           " stores none; bc6h-signed does)");
  return text;
}

MapSlot likelySlot(TextureFormat format) {
  switch (textureFormatInfo(format).layout) {
    case FormatLayout::R:
      return MapSlot::Height;
    case FormatLayout::NormalRg:
    case FormatLayout::NormalAg:
      return MapSlot::Normal;
    case FormatLayout::Rgb:
    case FormatLayout::Rgba:
    case FormatLayout::RgbHalf:  // an HDR image: colour, linear (decodeAsMap)
      return MapSlot::Color;
  }
  return MapSlot::Color;  // not reached: every layout is handled above
}

int likelySourceChannels(TextureFormat format) {
  const FormatLayout layout = textureFormatInfo(format).layout;
  return layout == FormatLayout::Rgba ? 4 : layout == FormatLayout::R ? 1 : 3;
}

CompressedTexture textureOfUnknownOrigin(TextureFormat format, bool srgb) {
  CompressedTexture texture;
  texture.format = format;
  texture.srgb = srgb;
  texture.slot = likelySlot(format);
  texture.sourceChannels = likelySourceChannels(format);
  return texture;
}

Result<std::vector<Image>> shippedMipLevels(const Image& map, MapSlot slot,
                                            const MipChainSpec& chain, const Image* spreadNormals) {
  if (!chain.mipmaps)
    return std::vector<Image>{};
  if (chain.foldNormalSpread && slot == MapSlot::Roughness) {
    if (!spreadNormals)
      return makeError("folding the normals' spread into roughness needs the normal map");
    if (spreadNormals->width() != map.width() || spreadNormals->height() != map.height()) {
      return makeError(
          "folding the normals' spread into roughness needs the normal map at the "
          "roughness map's size (" +
          std::to_string(map.width()) + "x" + std::to_string(map.height()) + "), not " +
          std::to_string(spreadNormals->width()) + "x" + std::to_string(spreadNormals->height()));
    }
    return foldedRoughnessLevels(map, *spreadNormals, chain.filter);
  }
  // Keeping alpha coverage, each level is filtered from the level above before its scale (the
  // scales do not compound) and scaled to level 0's coverage.
  const bool keepCoverage = chain.alphaCutoff > 0.0f && map.channels() >= 4;
  const double coverage = keepCoverage ? alphaCoverage(map, chain.alphaCutoff) : 0.0;
  std::vector<Image> smaller;
  Image unscaled;
  for (int i = 1, count = mipLevelCount(map.width(), map.height()); i < count; ++i) {
    const Image& above = i == 1 ? map : keepCoverage ? unscaled : smaller.back();
    Image level = downsampleForSlot(above, slot, chain.filter);
    if (keepCoverage) {
      unscaled = level;
      scaleAlphaToCoverage(level, chain.alphaCutoff, coverage);
    }
    smaller.push_back(std::move(level));
  }
  return smaller;
}

Result<CompressedTexture> compressMap(const Image& map, MapSlot slot,
                                      const CompressionSettings& settings,
                                      const WorkControl& control, const Image* spreadNormals) {
  if (map.isEmpty())
    return makeError("the map is empty");
  if (!formatSuitsSlot(settings.format, slot)) {
    return makeError(std::string(textureFormatInfo(settings.format).label) + " cannot hold a " +
                     std::string(mapSlotLabel(slot)) + " map");
  }
  CompressedTexture texture;
  texture.format = settings.format;
  texture.slot = slot;
  texture.sourceChannels = map.channels();
  texture.srgb = slot == MapSlot::Color && textureFormatInfo(settings.format).srgbVkFormat != 0;

  // Level 0 is the map itself (not copied: a 4096^2 float map is 200 MB). Half floats hold
  // linear colour (formatMapProblem refuses sRGB), so its mips average as data does, without
  // the sRGB round trip and its clamp to 0..1.
  const MapSlot filterSlot =
      isHalfFloatFormat(settings.format) && slot == MapSlot::Color ? MapSlot::Height : slot;
  Result<std::vector<Image>> levels =
      shippedMipLevels(map, filterSlot, shippedMipChain(settings), spreadNormals);
  if (!levels)
    return makeError(levels.error());
  const std::vector<Image>& smaller = levels.value();
  std::vector<const Image*> chain = {&map};
  for (const Image& level : smaller)
    chain.push_back(&level);
  double totalPixels = 0.0;
  for (const Image* level : chain)
    totalPixels += double(level->pixelCount());

  double done = 0.0;
  for (const Image* levelPointer : chain) {
    const Image& level = *levelPointer;
    const double share = double(level.pixelCount()) / totalPixels;
    const WorkControl part = slice(control, done / totalPixels, share);
    CompressedLevel compressed{level.width(), level.height(), {}};
    if (isAstc(settings.format)) {
      auto encoded = encodeAstc(settings.format, settings.quality, texture.srgb,
                                prepare(level, slot, settings.format), part);
      if (!encoded)
        return makeError(encoded.error());
      compressed.data = std::move(encoded).value();
    } else if (!encodeBlocks(level, slot, settings, compressed.data, part)) {
      return makeError("cancelled");
    }
    texture.levels.push_back(std::move(compressed));
    done += double(level.pixelCount());
  }
  control.report(1.0);
  return texture;
}

Result<Image> decodeLevel(const CompressedTexture& texture, int levelIndex) {
  if (levelIndex < 0 || levelIndex >= int(texture.levels.size()))
    return makeError("no mip level " + std::to_string(levelIndex));
  const CompressedLevel& level = texture.levels[std::size_t(levelIndex)];
  const TextureFormatInfo& info = textureFormatInfo(texture.format);
  if (level.data.size() < compressedLevelSize(texture.format, level.width, level.height))
    return makeError("level " + std::to_string(levelIndex) + " holds fewer bytes than its size");
  if (isAstc(texture.format)) {
    return decodeAstc(texture.format, texture.srgb, level.data.data(), level.data.size(),
                      level.width, level.height);
  }
  Image decoded(level.width, level.height, 4, texture.srgb ? ColorSpace::Srgb : ColorSpace::Linear);
  const int blocksX = (level.width + 3) / 4, blocksY = (level.height + 3) / 4;
  parallelFor(blocksY, [&](int by) {
    BlockTexels texels;
    for (int bx = 0; bx < blocksX; ++bx) {
      const std::uint8_t* block =
          level.data.data() + (std::size_t(by) * std::size_t(blocksX) + std::size_t(bx)) *
                                  std::size_t(info.bytesPerBlock);
      if (isBcFamily(texture.format))
        decodeBcBlock(texture.format, block, texels);
      else
        decodeEtcBlock(texture.format, block, texels);
      for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
          const int x = bx * 4 + i, y = by * 4 + j;
          if (x < level.width && y < level.height)
            std::copy(texels[j * 4 + i], texels[j * 4 + i] + 4, decoded.pixel(x, y));
        }
      }
    }
  });
  return decoded;
}

Result<Image> decodeAsMap(const CompressedTexture& texture, int levelIndex) {
  Result<Image> rgba = decodeLevel(texture, levelIndex);
  if (!rgba)
    return rgba;
  const FormatLayout layout = textureFormatInfo(texture.format).layout;
  const MapSlot slot = texture.slot;
  const int channels = slot == MapSlot::Color    ? std::clamp(texture.sourceChannels, 3, 4)
                       : slot == MapSlot::Normal ? 3
                                                 : 1;
  const bool halfFloat = isHalfFloatFormat(texture.format);
  Image map(rgba->width(), rgba->height(), channels,
            halfFloat ? ColorSpace::Linear : mapSlotColorSpace(slot));
  map.setSourceBitsPerChannel(halfFloat ? 16 : 8);
  for (std::size_t p = 0; p < map.pixelCount(); ++p) {
    const float* in = rgba->data() + p * 4;
    float* out = map.data() + p * std::size_t(channels);
    if (slot == MapSlot::Normal &&
        (layout == FormatLayout::NormalRg || layout == FormatLayout::NormalAg)) {
      // Reference 003, eq. 2.1: z = sqrt(1 - x^2 - y^2) from the two stored components.
      const float x = (layout == FormatLayout::NormalAg ? in[3] : in[0]) * 2.0f - 1.0f;
      const float y = in[1] * 2.0f - 1.0f;
      const float z = std::sqrt(std::max(0.0f, 1.0f - x * x - y * y));
      out[0] = x * 0.5f + 0.5f;
      out[1] = y * 0.5f + 0.5f;
      out[2] = z * 0.5f + 0.5f;
    } else {
      std::copy(in, in + channels, out);
    }
  }
  return map;
}

}  // namespace relief::core::inline compression
