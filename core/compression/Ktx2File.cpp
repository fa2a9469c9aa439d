// KTX2 reading and writing; see TextureFile.h. Layout from the KTX File Format Specification
// 2.0: identifier, header (vkFormat, typeSize, size, layer/face/level counts, supercompression),
// index (DFD, key/value data, supercompression data), level index (level 0 first), the Data
// Format Descriptor, key/value data, then the levels from the smallest to level 0, each at an
// offset aligned to lcm(block size, 4), or with Zstandard supercompression (scheme 2) each
// level compressed on its own, unaligned, with its size before compression in the level index. The
// descriptor follows the Khronos Data Format Specification 1.3 for compressed formats: one sample
// per 64-bit (or 128-bit ASTC) plane.
#include "core/compression/ByteStream.h"
#include "core/compression/MipChain.h"
#include "core/compression/TextureFile.h"

#include <zstd.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <stdexcept>
#include <thread>

namespace relief::core::inline compression {
namespace {

constexpr std::array<std::uint8_t, 12> kIdentifier = {0xAB, 'K',  'T',  'X',  ' ',  '2',
                                                      '0',  0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
constexpr std::size_t kHeaderEnd = 12 + 9 * 4 + 4 * 4 + 2 * 8;  // identifier, header, index

// Khronos Data Format channel ids and transfer functions (the colour models are in the format
// table, TextureFormat.cpp).
constexpr std::uint32_t kChannelColorBc = 0, kChannelRed = 0, kChannelGreen = 1,
                        kChannelEtc2Color = 2, kChannelAlpha = 15;
// Sample qualifiers (the top bits of the channel byte) and the float limits BC6H's sample uses.
constexpr std::uint32_t kQualifierFloat = 0x80, kQualifierSigned = 0x40;
constexpr std::uint32_t kFloatOne = 0x3F800000u, kFloatMinusOne = 0xBF800000u;
constexpr std::uint32_t kPrimariesBt709 = 1, kTransferLinear = 1, kTransferSrgb = 2;
constexpr std::string_view kSlotKey = "ReliefMapSlot", kChannelsKey = "ReliefSourceChannels";
constexpr std::string_view kSwizzleKey = "KTXswizzle", kNormalAgSwizzle = "ag01";
constexpr std::uint32_t kSchemeNone = 0, kSchemeZstd = 2;

// One level through Zstandard, with every core (libzstd's own workers).
std::vector<std::uint8_t> zstdCompress(const std::vector<std::uint8_t>& data, int level) {
  std::vector<std::uint8_t> out(ZSTD_compressBound(data.size()));
  ZSTD_CCtx* context = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(context, ZSTD_c_compressionLevel, level);
  // A 4-byte checksum per frame, so a damaged file is refused instead of decoded to wrong
  // blocks of the right size.
  ZSTD_CCtx_setParameter(context, ZSTD_c_checksumFlag, 1);
  // Fails harmlessly (one thread) on a libzstd built without threads.
  ZSTD_CCtx_setParameter(context, ZSTD_c_nbWorkers, int(std::thread::hardware_concurrency()));
  const std::size_t size =
      ZSTD_compress2(context, out.data(), out.size(), data.data(), data.size());
  ZSTD_freeCCtx(context);
  // Compressing into compressBound's room cannot fail for want of space; anything else is a
  // bug in the call, not in the data.
  if (ZSTD_isError(size))
    throw std::logic_error(std::string("ZSTD_compress2: ") + ZSTD_getErrorName(size));
  out.resize(size);
  return out;
}

struct Sample {
  std::uint32_t channel;
  std::uint32_t bitOffset;
};

std::vector<Sample> samples(Ktx2Samples layout) {
  switch (layout) {
    case Ktx2Samples::Whole:
      return {{kChannelColorBc, 0}};  // channel 0: BC colour, red, or ASTC's data
    case Ktx2Samples::EtcColour:
      return {{kChannelEtc2Color, 0}};
    case Ktx2Samples::AlphaThenColour:
      return {{kChannelAlpha, 0}, {kChannelColorBc, 64}};
    case Ktx2Samples::RedThenGreen:
      return {{kChannelRed, 0}, {kChannelGreen, 64}};
    case Ktx2Samples::AlphaThenEtcColour:
      return {{kChannelAlpha, 0}, {kChannelEtc2Color, 64}};
  }
  return {{0, 0}};  // not reached: every layout is handled above
}

std::vector<std::uint8_t> dataFormatDescriptor(const CompressedTexture& texture) {
  const TextureFormatInfo& info = textureFormatInfo(texture.format);
  const std::vector<Sample> blockSamples = samples(info.ktx2Samples);
  // The samples share the block: one spans it, two pair its 64-bit halves.
  const std::uint32_t sampleBits =
      std::uint32_t(info.bytesPerBlock) * 8 / std::uint32_t(blockSamples.size());
  const std::uint32_t blockSize = 24 + 16 * std::uint32_t(blockSamples.size());
  ByteWriter out;
  out.u32(4 + blockSize);        // dfdTotalSize
  out.u32(0);                    // vendorId 0 (Khronos), descriptorType 0 (basic)
  out.u32(2 | blockSize << 16);  // versionNumber 2, descriptorBlockSize
  out.u32(info.ktx2ColourModel | kPrimariesBt709 << 8 |
          (texture.srgb ? kTransferSrgb : kTransferLinear) << 16);  // flags 0: straight alpha
  out.u32(std::uint32_t(info.blockWidth - 1) | std::uint32_t(info.blockHeight - 1) << 8);
  out.u32(std::uint32_t(info.bytesPerBlock));  // bytesPlane0
  out.u32(0);                                  // bytesPlane4..7
  // BC6H's sample is flagged float (and signed for its signed form), and its limits are the
  // floats -1 or 0 and 1, as the specification's BC6H example gives them.
  const bool halfFloat = isHalfFloatFormat(texture.format);
  const bool isSigned = texture.format == TextureFormat::Bc6hSigned;
  const std::uint32_t qualifiers =
      (halfFloat ? kQualifierFloat : 0u) | (isSigned ? kQualifierSigned : 0u);
  for (const Sample& sample : blockSamples) {
    out.u32(sample.bitOffset | (sampleBits - 1) << 16 | (sample.channel | qualifiers) << 24);
    out.u32(0);                                                  // sample position 0, 0, 0, 0
    out.u32(halfFloat ? (isSigned ? kFloatMinusOne : 0u) : 0u);  // sampleLower
    out.u32(halfFloat ? kFloatOne : 0xFFFFFFFFu);                // sampleUpper
  }
  return std::move(out.data());
}

std::vector<std::uint8_t> keyValueData(const CompressedTexture& texture) {
  // Keys sorted by their bytes, as the specification requires; each entry padded to 4.
  std::map<std::string, std::string> entries = {
      {"KTXwriter", "Relief"},
      {std::string(kSlotKey), std::string(mapSlotName(texture.slot))},
      {std::string(kChannelsKey), std::to_string(texture.sourceChannels)},
  };
  // X in alpha and Y in green (DXT5nm, ASTC normal): KTX 2.0's swizzle key says how to sample
  // them as X, Y in red and green, and tells these files from BC3 and ASTC RGB ones.
  if (textureFormatInfo(texture.format).layout == FormatLayout::NormalAg)
    entries.emplace(std::string(kSwizzleKey), std::string(kNormalAgSwizzle));
  ByteWriter out;
  for (const auto& [key, value] : entries) {
    out.u32(std::uint32_t(key.size() + 1 + value.size() + 1));
    out.text(key);
    out.u8(0);
    out.text(value);
    out.u8(0);
    out.padTo(4);
  }
  return std::move(out.data());
}

std::optional<TextureFormat> formatForVk(std::uint32_t vkFormat, bool& srgb) {
  for (const TextureFormatInfo& info : allTextureFormats()) {
    // DXT5nm shares BC3's code, the ASTC normal formats their RGB ones', and ETC2 RGB ETC1's;
    // the first row wins (BC3, ASTC; ETC1 is ETC2's subset, so the stream is read as ETC2 RGB).
    if (info.layout == FormatLayout::NormalAg || info.format == TextureFormat::Etc1)
      continue;
    if (info.vkFormat == vkFormat || (info.srgbVkFormat != 0 && info.srgbVkFormat == vkFormat)) {
      srgb = info.srgbVkFormat == vkFormat;
      return info.format;
    }
  }
  return std::nullopt;
}

}  // namespace

std::vector<std::uint8_t> encodeKtx2(const CompressedTexture& texture, int zstdLevel) {
  const bool zstd = zstdLevel > 0;
  const TextureFormatInfo& info = textureFormatInfo(texture.format);
  const std::vector<std::uint8_t> dfd = dataFormatDescriptor(texture);
  const std::vector<std::uint8_t> kvd = keyValueData(texture);
  const std::size_t levelCount = texture.levels.size();
  ByteWriter out;
  out.bytes(kIdentifier.data(), kIdentifier.size());
  out.u32(texture.srgb && info.srgbVkFormat ? info.srgbVkFormat : info.vkFormat);
  out.u32(1);  // typeSize: 1 for block-compressed formats
  out.u32(std::uint32_t(texture.levels.empty() ? 0 : texture.levels[0].width));
  out.u32(std::uint32_t(texture.levels.empty() ? 0 : texture.levels[0].height));
  out.u32(0);  // pixelDepth
  out.u32(0);  // layerCount: not an array
  out.u32(1);  // faceCount
  out.u32(std::uint32_t(levelCount));
  out.u32(zstd ? kSchemeZstd : kSchemeNone);
  const std::size_t dfdOffset = kHeaderEnd + levelCount * 24;
  const std::size_t kvdOffset = dfdOffset + dfd.size();
  out.u32(std::uint32_t(dfdOffset));
  out.u32(std::uint32_t(dfd.size()));
  out.u32(std::uint32_t(kvdOffset));
  out.u32(std::uint32_t(kvd.size()));
  out.u64(0);  // sgdByteOffset
  out.u64(0);  // sgdByteLength
  const std::size_t levelIndex = out.size();
  out.zeros(levelCount * 24);
  out.bytes(dfd.data(), dfd.size());
  out.bytes(kvd.data(), kvd.size());
  // Supercompressed levels are not aligned (KTX2 3.13: lcm is 1 then).
  const std::size_t alignment =
      zstd ? 1 : std::lcm(std::size_t(info.bytesPerBlock), std::size_t(4));
  for (std::size_t i = levelCount; i-- > 0;) {  // smallest level first
    out.padTo(alignment);
    const CompressedLevel& level = texture.levels[i];
    const std::vector<std::uint8_t> stored =
        zstd ? zstdCompress(level.data, std::min(zstdLevel, kMaxZstdLevel)) : level.data;
    out.patchU64(levelIndex + i * 24, out.size());
    out.patchU64(levelIndex + i * 24 + 8, stored.size());
    out.patchU64(levelIndex + i * 24 + 16, level.data.size());  // uncompressedByteLength
    out.bytes(stored.data(), stored.size());
  }
  return std::move(out.data());
}

namespace {

// Reads Relief's own keys (the map's slot, its source channels, the normal swizzle) from the
// key/value data into `texture`; other writers' keys are skipped. Returns whether the swizzle
// says X is in alpha.
bool readReliefKeys(const std::vector<std::uint8_t>& bytes, std::uint32_t kvdOffset,
                    std::uint32_t kvdLength, CompressedTexture& texture) {
  bool normalAg = false;
  std::size_t at = kvdOffset;
  const std::size_t end = std::size_t(kvdOffset) + kvdLength;
  while (at + 4 <= end) {
    ByteReader entry(bytes, at);
    const std::uint32_t length = entry.u32();
    if (length == 0 || length > end - at - 4)
      break;
    const std::string pair(bytes.begin() + std::ptrdiff_t(at + 4),
                           bytes.begin() + std::ptrdiff_t(at + 4 + length));
    const std::size_t zero = pair.find('\0');
    if (zero != std::string::npos) {
      const std::string key = pair.substr(0, zero);
      std::string value = pair.substr(zero + 1);
      if (!value.empty() && value.back() == '\0')
        value.pop_back();
      if (key == kSlotKey) {
        if (const std::optional<MapSlot> slot = findMapSlot(value))
          texture.slot = *slot;
      } else if (key == kChannelsKey && value.size() == 1 && value[0] >= '1' && value[0] <= '4') {
        texture.sourceChannels = value[0] - '0';
      } else if (key == kSwizzleKey) {
        normalAg = value == kNormalAgSwizzle;
      }
    }
    at += 4 + ((length + 3) / 4) * 4;
  }
  return normalAg;
}

// One mip level's blocks at its entry in the level index, inflated when the file is
// Zstandard-supercompressed; fails with what is wrong in `name`.
Result<CompressedLevel> readLevel(const std::vector<std::uint8_t>& bytes, int level,
                                  TextureFormat format, int w, int h, bool zstd,
                                  const std::string& name) {
  const auto fail = [&name](const std::string& problem) { return fileError(name, problem); };
  ByteReader entry(bytes, kHeaderEnd + std::size_t(level) * 24);
  const std::uint64_t offset = entry.u64(), length = entry.u64(), unpacked = entry.u64();
  if (!entry.ok())
    return fail("the level index is cut short");
  const std::uint64_t expected = compressedLevelSize(format, w, h);
  // Without supercompression the stored bytes are the blocks; with it, what they inflate to.
  const std::uint64_t blocks = zstd ? unpacked : length;
  if (blocks != expected)
    return fail("mip level " + std::to_string(level) + " holds " + std::to_string(blocks) +
                " bytes; a " + std::to_string(w) + "x" + std::to_string(h) + " level needs " +
                std::to_string(expected));
  if (offset > bytes.size() || length > bytes.size() - offset)
    return fail("mip level " + std::to_string(level) + " lies outside the file (bytes " +
                std::to_string(offset) + ".." + std::to_string(offset + length) + " of " +
                std::to_string(bytes.size()) + ")");
  CompressedLevel compressed{w, h, {}};
  if (zstd) {
    // The output is sized by the level's dimensions (already within the limits), never by
    // what the frame claims; a frame that inflates to anything else is refused.
    compressed.data.resize(std::size_t(expected));
    const std::size_t inflated = ZSTD_decompress(compressed.data.data(), compressed.data.size(),
                                                 bytes.data() + offset, std::size_t(length));
    if (ZSTD_isError(inflated) || inflated != expected) {
      return fail("mip level " + std::to_string(level) + ": the Zstandard data is damaged (" +
                  (ZSTD_isError(inflated) ? std::string(ZSTD_getErrorName(inflated))
                                          : std::to_string(inflated) + " bytes instead of " +
                                                std::to_string(expected)) +
                  ")");
    }
  } else {
    compressed.data.assign(bytes.begin() + std::ptrdiff_t(offset),
                           bytes.begin() + std::ptrdiff_t(offset + length));
  }
  return compressed;
}

}  // namespace

Result<CompressedTexture> decodeKtx2(const std::vector<std::uint8_t>& bytes,
                                     const std::string& name) {
  const auto fail = [&name](const std::string& problem) { return fileError(name, problem); };
  if (bytes.size() < kIdentifier.size() ||
      !std::equal(kIdentifier.begin(), kIdentifier.end(), bytes.begin()))
    return fail("not a KTX2 file (no KTX 20 identifier)");
  ByteReader in(bytes, kIdentifier.size());
  const std::uint32_t vkFormat = in.u32(), typeSize = in.u32(), width = in.u32(), height = in.u32(),
                      depth = in.u32(), layers = in.u32(), faces = in.u32(), levelCount = in.u32(),
                      supercompression = in.u32();
  const std::uint32_t dfdOffset = in.u32(), dfdLength = in.u32();
  const std::uint32_t kvdOffset = in.u32(), kvdLength = in.u32();
  const std::uint64_t sgdOffset = in.u64(), sgdLength = in.u64();
  if (!in.ok())
    return fail("the file is shorter than a KTX2 header (" + std::to_string(bytes.size()) +
                " bytes)");
  bool srgb = false;
  const std::optional<TextureFormat> format = formatForVk(vkFormat, srgb);
  if (!format)
    return fail("vkFormat " + std::to_string(vkFormat) + " is not one Relief reads");
  if (typeSize != 1)
    return fail("typeSize " + std::to_string(typeSize) + " is wrong for a compressed format");
  if (supercompression != kSchemeNone && supercompression != kSchemeZstd)
    return fail("supercompression scheme " + std::to_string(supercompression) +
                " is not supported (uncompressed and Zstandard levels are read)");
  // Every index range lies inside the file, even those this reader does not use: a file that
  // claims 4 GiB of key/value data is damaged, whatever else it holds (KTX2 3.9-3.11).
  const auto outside = [&bytes](std::uint64_t offset, std::uint64_t length) {
    return offset > bytes.size() || length > bytes.size() - offset;
  };
  if (outside(dfdOffset, dfdLength))
    return fail("its data format descriptor lies outside the file");
  if (outside(kvdOffset, kvdLength))
    return fail("its key/value data (" + std::to_string(kvdLength) + " bytes at " +
                std::to_string(kvdOffset) + ") lies outside the file");
  if (outside(sgdOffset, sgdLength) || (sgdLength > 0 && supercompression == 0))
    return fail("its supercompression data (" + std::to_string(sgdLength) + " bytes at " +
                std::to_string(sgdOffset) + ") lies outside the file or belongs to no scheme");
  if (depth > 1 || layers > 1 || faces != 1)
    return fail("only single 2D textures are read (not arrays, cube maps or volumes)");
  if (std::string problem = textureExtentProblem(width, height, levelCount); !problem.empty())
    return fail(problem);
  // levelCount 0 means the base level only, with the rest to be generated (KTX2 3.7).
  const int levels = int(std::max<std::uint32_t>(levelCount, 1));

  CompressedTexture texture = textureOfUnknownOrigin(*format, srgb);
  texture.zstdInFile = supercompression == kSchemeZstd;

  // Our own keys say what the map was; other writers' files fall back to the layout's guess.
  const bool normalAg = kvdLength > 0 && readReliefKeys(bytes, kvdOffset, kvdLength, texture);
  // The X-in-alpha normal formats share their codes: the swizzle key marks them (and, from
  // files written before it was, a BC3 file holding a normal map is DXT5nm).
  if (normalAg || (texture.slot == MapSlot::Normal && *format == TextureFormat::Bc3)) {
    for (const TextureFormatInfo& info : allTextureFormats()) {
      if (info.layout == FormatLayout::NormalAg &&
          info.vkFormat == textureFormatInfo(*format).vkFormat)
        texture.format = info.format;
    }
  }

  int w = int(width), h = int(height);
  for (int level = 0; level < levels; ++level) {
    Result<CompressedLevel> compressed =
        readLevel(bytes, level, *format, w, h, texture.zstdInFile, name);
    if (!compressed)
      return makeError(compressed.error());
    texture.levels.push_back(std::move(compressed).value());
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
  }
  return texture;
}

}  // namespace relief::core::inline compression
