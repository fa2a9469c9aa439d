// DDS and KTX2 files: headers checked field by field against the specifications (Microsoft's
// DDS guide, KTX 2.0 and the Khronos Data Format Specification), DDS files opened by
// independent readers (OpenImageIO, Pillow) with the pixels our decoder gives, and hostile
// files (truncated, wrong sizes, enormous dimensions, too many levels) refused with errors.
#include "core/compression/ByteStream.h"
#include "core/compression/Compressor.h"
#include "core/compression/TextureFile.h"
#include "support/TestPaths.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <QProcess>

#include <filesystem>
#include <fstream>

namespace relief::core {
namespace {

Image testPattern(int width, int height, int channels) {
  Image image(width, height, channels, ColorSpace::Srgb);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < channels; ++c) {
        image.at(x, y, c) =
            0.5f + 0.45f * std::sin(0.3f * float(x) * float(c + 1) + 0.17f * float(y) - float(c));
      }
    }
  }
  return image;
}

Image unitNormals(int width, int height) {
  Image image(width, height, 3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const float nx = 0.5f * std::sin(0.2f * float(x)), ny = 0.4f * std::cos(0.3f * float(y));
      const float nz = std::sqrt(1.0f - nx * nx - ny * ny);
      image.at(x, y, 0) = 0.5f + 0.5f * nx;
      image.at(x, y, 1) = 0.5f + 0.5f * ny;
      image.at(x, y, 2) = 0.5f + 0.5f * nz;
    }
  }
  return image;
}

CompressedTexture compressed(TextureFormat format, int width = 36, int height = 20,
                             bool mips = true) {
  const MapSlot slot = likelySlot(format);
  const Image map = slot == MapSlot::Normal   ? unitNormals(width, height)
                    : slot == MapSlot::Height ? testPattern(width, height, 1)
                                              : testPattern(width, height, 4);
  return compressMap(map, slot, {format, CompressionQuality::Fast, mips}).value();
}

std::uint32_t u32At(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return ByteReader(bytes, at).u32();
}
std::uint64_t u64At(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return ByteReader(bytes, at).u64();
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// --- DDS -------------------------------------------------------------------------------------

TEST(DdsFileTest, HeaderUsesTheLegacyFourCCAndRoundTrips) {
  const std::pair<TextureFormat, const char*> cases[] = {
      {TextureFormat::Bc1, "DXT1"}, {TextureFormat::Bc2, "DXT3"}, {TextureFormat::Bc3, "DXT5"},
      {TextureFormat::Bc4, "ATI1"}, {TextureFormat::Bc5, "ATI2"}, {TextureFormat::Dxt5nm, "DXT5"}};
  for (const auto& [format, fourCC] : cases) {
    const CompressedTexture texture = compressed(format);
    const std::vector<std::uint8_t> bytes = encodeDds(texture).value();
    EXPECT_EQ(u32At(bytes, 0), makeFourCC('D', 'D', 'S', ' '));
    EXPECT_EQ(u32At(bytes, 4), 124u);                            // dwSize
    EXPECT_EQ(u32At(bytes, 12), 20u);                            // dwHeight
    EXPECT_EQ(u32At(bytes, 16), 36u);                            // dwWidth
    EXPECT_EQ(u32At(bytes, 20), texture.levels[0].data.size());  // linear size of level 0
    EXPECT_EQ(u32At(bytes, 28), 6u);                             // 36x20 .. 1x1
    EXPECT_EQ(u32At(bytes, 76), 32u);                            // ddspf.dwSize
    EXPECT_EQ(u32At(bytes, 84), makeFourCC(fourCC[0], fourCC[1], fourCC[2], fourCC[3]));
    // DDPF_FOURCC, and DDPF_NORMAL only for DXT5nm.
    EXPECT_EQ(u32At(bytes, 80), format == TextureFormat::Dxt5nm ? 0x80000004u : 0x4u);
    EXPECT_EQ(bytes.size(), 128 + texture.byteSize());

    Result<CompressedTexture> back = decodeDds(bytes, "t.dds");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(back->format, format);
    ASSERT_EQ(back->levels.size(), texture.levels.size());
    for (std::size_t i = 0; i < texture.levels.size(); ++i)
      EXPECT_EQ(back->levels[i].data, texture.levels[i].data) << "level " << i;
  }
  Result<std::vector<std::uint8_t>> etc = encodeDds(compressed(TextureFormat::Etc2A));
  ASSERT_FALSE(etc.ok());
  EXPECT_NE(etc.error().find(".ktx2"), std::string::npos);
}

// BC7 has no legacy FourCC: "DX10" and DDS_HEADER_DXT10 with DXGI_FORMAT_BC7_UNORM (98) or
// _UNORM_SRGB (99), TEXTURE2D (3), no flags, array size 1 (Microsoft's DDS_HEADER_DXT10).
TEST(DdsFileTest, Bc7IsWrittenWithTheDx10Header) {
  for (const bool srgb : {false, true}) {
    CompressedTexture texture = compressed(TextureFormat::Bc7);
    texture.srgb = srgb;
    const std::vector<std::uint8_t> bytes = encodeDds(texture).value();
    EXPECT_EQ(u32At(bytes, 80), 0x4u);  // DDPF_FOURCC
    EXPECT_EQ(u32At(bytes, 84), makeFourCC('D', 'X', '1', '0'));
    EXPECT_EQ(u32At(bytes, 128), srgb ? 99u : 98u);
    EXPECT_EQ(u32At(bytes, 132), 3u);
    EXPECT_EQ(u32At(bytes, 136), 0u);
    EXPECT_EQ(u32At(bytes, 140), 1u);
    EXPECT_EQ(bytes.size(), 148 + texture.byteSize());
    Result<CompressedTexture> back = decodeDds(bytes, "bc7.dds");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_EQ(back->format, TextureFormat::Bc7);
    EXPECT_EQ(back->srgb, srgb);
    ASSERT_EQ(back->levels.size(), texture.levels.size());
    for (std::size_t i = 0; i < texture.levels.size(); ++i)
      EXPECT_EQ(back->levels[i].data, texture.levels[i].data) << "level " << i;
  }
}

TEST(DdsFileTest, Dx10HeadersFromOtherToolsAreRead) {
  // The same BC3 blocks behind a DX10 header with DXGI_FORMAT_BC3_UNORM_SRGB (78).
  const CompressedTexture texture = compressed(TextureFormat::Bc3, 8, 8, false);
  std::vector<std::uint8_t> bytes = encodeDds(texture).value();
  ByteWriter dx10;
  for (std::uint32_t value : {78u, 3u, 0u, 1u, 0u})  // format, TEXTURE2D, flags, array 1, misc
    dx10.u32(value);
  bytes.insert(bytes.begin() + 128, dx10.data().begin(), dx10.data().end());
  bytes[84] = 'D', bytes[85] = 'X', bytes[86] = '1', bytes[87] = '0';
  Result<CompressedTexture> back = decodeDds(bytes, "dx10.dds");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->format, TextureFormat::Bc3);
  EXPECT_TRUE(back->srgb);
  EXPECT_EQ(back->levels[0].data, texture.levels[0].data);
}

// The channels a BC format holds (BC1 here is opaque RGB).
int channelsHeld(TextureFormat format) {
  switch (format) {
    case TextureFormat::Bc4:
      return 1;
    case TextureFormat::Bc5:
      return 2;
    case TextureFormat::Bc1:
      return 3;
    default:
      return 4;
  }
}

// The decoded texels as 8-bit values, for comparing with readers that decode to 8 bits.
float channelOf(const Image& image, int x, int y, int c) {
  return image.at(x, y, std::min(c, image.channels() - 1));
}

TEST(DdsFileTest, OpenImageIOReadsOurFilesWithOurPixels) {
  const std::string folder = test::scratchFolder();
  for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc2, TextureFormat::Bc3,
                               TextureFormat::Bc4, TextureFormat::Bc5, TextureFormat::Bc7}) {
    CompressedTexture texture = compressed(format, 36, 20, true);
    // OpenImageIO 2.4 refuses sRGB DXGI codes (BC7's DX10 header would say 99); the blocks
    // are the same either way.
    texture.srgb = false;
    const std::string path =
        folder + "/oiio-" + std::string(textureFormatInfo(format).name) + ".dds";
    ASSERT_TRUE(saveCompressedTexture(texture, path).ok());
    // Saved as header and levels without joining them: the file is encodeDds's bytes.
    std::ifstream saved(path, std::ios::binary);
    const std::vector<std::uint8_t> file{std::istreambuf_iterator<char>(saved), {}};
    EXPECT_EQ(file, encodeDds(texture).value());
    const Image ours = decodeLevel(texture).value();

    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input) << OIIO::geterror();
    const OIIO::ImageSpec& spec = input->spec();
    ASSERT_EQ(spec.width, 36);
    ASSERT_EQ(spec.height, 20);
    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) *
                              std::size_t(spec.nchannels));
    ASSERT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    // OpenImageIO gives BC4 one channel and BC5 red and green (with a blue it may rebuild);
    // the channels both hold must agree within the rounding of 8-bit interpolation.
    const int compared = channelsHeld(format);
    double worst = 0.0;
    for (int y = 0; y < 20; ++y) {
      for (int x = 0; x < 36; ++x) {
        for (int c = 0; c < std::min(compared, spec.nchannels); ++c) {
          const float theirs =
              pixels[(std::size_t(y) * 36 + std::size_t(x)) * std::size_t(spec.nchannels) +
                     std::size_t(c)];
          worst = std::max(worst, double(std::abs(theirs - channelOf(ours, x, y, c))));
        }
      }
    }
    EXPECT_LE(worst, 1.01 / 255.0) << textureFormatInfo(format).name;
  }
}

TEST(DdsFileTest, PillowReadsOurFilesWithOurPixels) {
  const std::string folder = test::scratchFolder();
  // Pillow (9.4, Debian 12) reads DXT1, DXT3, DXT5, ATI1, ATI2 and DX10 BC7 (its own C
  // decoder, independent of ours).
  for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc2, TextureFormat::Bc3,
                               TextureFormat::Bc4, TextureFormat::Bc5, TextureFormat::Bc7}) {
    const CompressedTexture texture = compressed(format, 36, 20, false);
    const std::string name = std::string(textureFormatInfo(format).name);
    const std::string dds = folder + "/pil-" + name + ".dds";
    const std::string raw = folder + "/pil-" + name + ".raw";
    ASSERT_TRUE(saveCompressedTexture(texture, dds).ok());
    QProcess python;
    python.start("/usr/bin/python3",
                 {"-c",
                  "import sys; from PIL import Image; im = Image.open(sys.argv[1]); "
                  "im = im.convert('RGBA'); open(sys.argv[2], 'wb').write(im.tobytes()); "
                  "print(im.size[0], im.size[1])",
                  QString::fromStdString(dds), QString::fromStdString(raw)});
    ASSERT_TRUE(python.waitForFinished(60000));
    ASSERT_EQ(python.exitCode(), 0) << python.readAllStandardError().toStdString();
    EXPECT_EQ(python.readAllStandardOutput().trimmed().toStdString(), "36 20");
    std::ifstream file(raw, std::ios::binary);
    std::vector<unsigned char> rgba(36 * 20 * 4);
    ASSERT_TRUE(file.read(reinterpret_cast<char*>(rgba.data()), std::streamsize(rgba.size())));
    const Image ours = decodeLevel(texture).value();
    // Pillow shows BC4 as grey (L), BC5 as red and green.
    const int compared = channelsHeld(format);
    double worst = 0.0;
    for (int y = 0; y < 20; ++y) {
      for (int x = 0; x < 36; ++x) {
        for (int c = 0; c < compared; ++c) {
          const float theirs =
              float(rgba[(std::size_t(y) * 36 + std::size_t(x)) * 4 + std::size_t(c)]) / 255.0f;
          worst = std::max(worst, double(std::abs(theirs - channelOf(ours, x, y, c))));
        }
      }
    }
    EXPECT_LE(worst, 1.01 / 255.0) << name;
  }
}

// --- KTX2 ------------------------------------------------------------------------------------

// The Khronos Data Format Specification 1.3, section 5.6: every BC format is one of the
// KHR_DF_MODEL_BC1A..BC7 models (128..134), ETC1 is 160, ETC2 and EAC 161, ASTC 162. Each
// format's descriptor names its family's model; the ASTC normal formats once fell through to
// ETC2's.
TEST(Ktx2FileTest, EveryFormatsDescriptorNamesItsFamilysColourModel) {
  for (const TextureFormatInfo& info : allTextureFormats()) {
    const std::vector<std::uint8_t> bytes = encodeKtx2(compressed(info.format, 8, 8, false));
    const std::uint32_t model = u32At(bytes, u32At(bytes, 48) + 12) & 0xFF;
    switch (info.family) {
      case FormatFamily::Bc:
        EXPECT_GE(model, 128u) << info.name;
        EXPECT_LE(model, 134u) << info.name;
        break;
      case FormatFamily::Etc:
        EXPECT_TRUE(model == 160u || model == 161u) << info.name << ": " << model;
        break;
      case FormatFamily::Astc:
        EXPECT_EQ(model, 162u) << info.name;
        break;
    }
  }
}

TEST(Ktx2FileTest, HeaderIndexAndDescriptorFollowTheSpecification) {
  const CompressedTexture texture = compressed(TextureFormat::Astc6x6, 37, 23, true);
  ASSERT_EQ(texture.levels.size(), 6u);  // 37x23, 18x11, 9x5, 4x2, 2x1, 1x1
  const std::vector<std::uint8_t> bytes = encodeKtx2(texture);
  const std::uint8_t identifier[12] = {0xAB, 'K',  'T',  'X',  ' ',  '2',
                                       '0',  0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  EXPECT_TRUE(std::equal(identifier, identifier + 12, bytes.begin()));
  EXPECT_EQ(u32At(bytes, 12), 166u);  // VK_FORMAT_ASTC_6x6_SRGB_BLOCK (a colour map)
  EXPECT_EQ(u32At(bytes, 16), 1u);    // typeSize
  EXPECT_EQ(u32At(bytes, 20), 37u);
  EXPECT_EQ(u32At(bytes, 24), 23u);
  EXPECT_EQ(u32At(bytes, 28), 0u);  // pixelDepth
  EXPECT_EQ(u32At(bytes, 32), 0u);  // layerCount
  EXPECT_EQ(u32At(bytes, 36), 1u);  // faceCount
  EXPECT_EQ(u32At(bytes, 40), 6u);  // levelCount
  EXPECT_EQ(u32At(bytes, 44), 0u);  // supercompressionScheme
  const std::uint32_t dfdOffset = u32At(bytes, 48), dfdLength = u32At(bytes, 52);
  const std::uint32_t kvdOffset = u32At(bytes, 56), kvdLength = u32At(bytes, 60);
  EXPECT_EQ(dfdOffset, 80u + 6u * 24u);  // right after the level index
  EXPECT_EQ(kvdOffset, dfdOffset + dfdLength);
  EXPECT_EQ(kvdLength % 4, 0u);
  EXPECT_EQ(u64At(bytes, 64), 0u);  // sgdByteOffset
  EXPECT_EQ(u64At(bytes, 72), 0u);

  // Level index: level 0 first; data stored smallest level first, each aligned to 16 (the
  // lcm of the 16-byte block and 4), lengths equal to whole blocks.
  std::uint64_t previousOffset = bytes.size();
  for (std::size_t level = 0; level < 6; ++level) {
    const std::uint64_t offset = u64At(bytes, 80 + level * 24);
    const std::uint64_t length = u64At(bytes, 88 + level * 24);
    EXPECT_EQ(u64At(bytes, 96 + level * 24), length);  // uncompressedByteLength
    EXPECT_EQ(length, texture.levels[level].data.size());
    EXPECT_EQ(offset % 16, 0u);
    EXPECT_LT(offset, previousOffset) << "level " << level << " must precede the larger ones";
    previousOffset = offset;
    EXPECT_TRUE(std::equal(texture.levels[level].data.begin(), texture.levels[level].data.end(),
                           bytes.begin() + std::ptrdiff_t(offset)));
  }
  EXPECT_EQ(u64At(bytes, 80) + u64At(bytes, 88), bytes.size());  // level 0 ends the file

  // Data Format Descriptor: total size, then a basic block (version 2) of 24 + 16 bytes.
  EXPECT_EQ(u32At(bytes, dfdOffset), dfdLength);
  EXPECT_EQ(u32At(bytes, dfdOffset + 4), 0u);  // vendor Khronos, type basic
  EXPECT_EQ(u32At(bytes, dfdOffset + 8), 2u | 40u << 16);
  const std::uint32_t model = u32At(bytes, dfdOffset + 12);
  EXPECT_EQ(model & 0xFF, 162u);                          // KHR_DF_MODEL_ASTC
  EXPECT_EQ((model >> 8) & 0xFF, 1u);                     // BT.709 primaries
  EXPECT_EQ((model >> 16) & 0xFF, 2u);                    // sRGB transfer
  EXPECT_EQ(u32At(bytes, dfdOffset + 16), 5u | 5u << 8);  // texelBlockDimension 6x6, minus one
  EXPECT_EQ(u32At(bytes, dfdOffset + 20), 16u);           // bytesPlane0
  EXPECT_EQ(u32At(bytes, dfdOffset + 28), 127u << 16);    // one 128-bit sample, channel 0
  EXPECT_EQ(u32At(bytes, dfdOffset + 40), 0xFFFFFFFFu);   // sampleUpper

  // Key/value data holds the writer and, sorted after it by byte order... all keys sorted.
  const std::string kvd(bytes.begin() + kvdOffset, bytes.begin() + kvdOffset + kvdLength);
  EXPECT_NE(kvd.find("KTXwriter"), std::string::npos);
  EXPECT_LT(kvd.find("KTXwriter"), kvd.find("ReliefMapSlot"));

  Result<CompressedTexture> back = decodeKtx2(bytes, "t.ktx2");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->format, TextureFormat::Astc6x6);
  EXPECT_TRUE(back->srgb);
  EXPECT_EQ(back->slot, MapSlot::Color);
  EXPECT_EQ(back->sourceChannels, 4);
  for (std::size_t level = 0; level < 6; ++level)
    EXPECT_EQ(back->levels[level].data, texture.levels[level].data);
}

TEST(Ktx2FileTest, EveryFormatRoundTripsWithItsDescriptor) {
  for (const TextureFormatInfo& info : allTextureFormats()) {
    const CompressedTexture texture = compressed(info.format, 20, 12, true);
    const std::vector<std::uint8_t> bytes = encodeKtx2(texture);
    Result<CompressedTexture> back = decodeKtx2(bytes, "t.ktx2");
    ASSERT_TRUE(back.ok()) << info.name << ": " << back.error();
    // ETC1 is written as ETC2 RGB (its superset); everything else comes back as it went.
    EXPECT_EQ(back->format, info.format == TextureFormat::Etc1 ? TextureFormat::Etc2 : info.format)
        << info.name;
    EXPECT_EQ(back->slot, texture.slot) << info.name;
    EXPECT_EQ(back->levels.size(), texture.levels.size());
    EXPECT_EQ(back->levels.back().data, texture.levels.back().data);
    // Two planes of 64 bits for the formats that pair two blocks: BC2/BC3, BC5, ETC2 RGBA, RG11;
    // ASTC, BC6H and BC7 blocks are one 128-bit sample.
    const std::uint32_t dfd = u32At(bytes, 48);
    const std::uint32_t samples = ((u32At(bytes, dfd + 8) >> 16) - 24) / 16;
    const bool oneBlock =
        isAstc(info.format) || info.format == TextureFormat::Bc7 || isHalfFloatFormat(info.format);
    EXPECT_EQ(samples, info.bytesPerBlock == 16 && !oneBlock ? 2u : 1u) << info.name;
    EXPECT_EQ(u32At(bytes, dfd + 20), std::uint32_t(info.bytesPerBlock)) << info.name;
    // BC6H's sample is float (0x80 in the channel byte), signed (0x40) in its signed form, with
    // the float limits 0 or -1 and 1 (Khronos Data Format 1.3, BC6H).
    if (isHalfFloatFormat(info.format)) {
      const std::uint32_t channel = u32At(bytes, dfd + 28) >> 24;
      const bool isSigned = info.format == TextureFormat::Bc6hSigned;
      EXPECT_EQ(channel, isSigned ? 0xC0u : 0x80u) << info.name;
      EXPECT_EQ(u32At(bytes, dfd + 36), isSigned ? 0xBF800000u : 0u) << info.name;
      EXPECT_EQ(u32At(bytes, dfd + 40), 0x3F800000u) << info.name;
    }
  }
}

// Zstandard supercompression (KTX2 scheme 2): each level is one Zstandard frame that the
// reference `zstd` tool (Debian's zstd package, independent of our reader) inflates to the
// level's blocks; the level index holds the stored and the inflated sizes (KTX2 3.9.7).
TEST(Ktx2FileTest, ZstandardLevelsInflateWithTheReferenceToolToTheBlocks) {
  const std::string folder = test::scratchFolder() + "/zstd";
  std::filesystem::create_directories(folder);
  for (const TextureFormat format :
       {TextureFormat::Bc1, TextureFormat::Bc5, TextureFormat::Etc2, TextureFormat::Astc4x4}) {
    const CompressedTexture texture = compressed(format, 64, 48, true);
    const std::vector<std::uint8_t> bytes = encodeKtx2(texture, 9);
    ASSERT_EQ(u32At(bytes, 44), 2u) << "supercompressionScheme";
    for (std::size_t level = 0; level < texture.levels.size(); ++level) {
      const std::uint64_t offset = u64At(bytes, 80 + 24 * level);
      const std::uint64_t stored = u64At(bytes, 88 + 24 * level);
      EXPECT_EQ(u64At(bytes, 96 + 24 * level), texture.levels[level].data.size());
      ASSERT_LE(offset + stored, bytes.size());
      const std::string frame = folder + "/level.zst";
      std::ofstream(frame, std::ios::binary)
          .write(reinterpret_cast<const char*>(bytes.data() + offset), std::streamsize(stored));
      QProcess zstd;
      zstd.start(QStringLiteral("zstd"),
                 {QStringLiteral("-d"), QStringLiteral("-c"), QString::fromStdString(frame)});
      ASSERT_TRUE(zstd.waitForFinished(30000)) << "the zstd tool (Debian package zstd)";
      ASSERT_EQ(zstd.exitCode(), 0) << zstd.readAllStandardError().toStdString();
      const QByteArray inflated = zstd.readAllStandardOutput();
      const std::vector<std::uint8_t>& blocks = texture.levels[level].data;
      ASSERT_EQ(std::size_t(inflated.size()), blocks.size()) << "level " << level;
      EXPECT_TRUE(std::equal(blocks.begin(), blocks.end(),
                             reinterpret_cast<const std::uint8_t*>(inflated.data())))
          << "level " << level;
    }
    // And our reader gives the same blocks back, knowing the file was supercompressed.
    Result<CompressedTexture> back = decodeKtx2(bytes, "z.ktx2");
    ASSERT_TRUE(back.ok()) << back.error();
    EXPECT_TRUE(back->zstdInFile);
    ASSERT_EQ(back->levels.size(), texture.levels.size());
    for (std::size_t level = 0; level < texture.levels.size(); ++level)
      EXPECT_EQ(back->levels[level].data, texture.levels[level].data);
  }
}

TEST(Ktx2FileTest, ZstandardMakesCompressibleBlocksSmallerAndDamageIsRefused) {
  // A constant map compresses to repeated blocks: Zstandard must shrink them a lot.
  Image flat(64, 64, 4, ColorSpace::Srgb);
  std::fill(flat.data(), flat.data() + flat.valueCount(), 0.5f);
  const CompressedTexture texture =
      compressMap(flat, MapSlot::Color, {TextureFormat::Bc1, CompressionQuality::Fast, false})
          .value();
  const std::vector<std::uint8_t> plain = encodeKtx2(texture);
  const std::vector<std::uint8_t> packed = encodeKtx2(texture, 3);
  EXPECT_LT(packed.size(), plain.size() - texture.levels[0].data.size() / 2);

  // A damaged frame, a frame that inflates to a different size, and a claimed size that is
  // not the level's are all refused by name.
  std::vector<std::uint8_t> damaged = packed;
  const std::uint64_t offset = u64At(packed, 80);
  damaged[std::size_t(offset) + 2] ^= 0xff;
  Result<CompressedTexture> bad = decodeKtx2(damaged, "damaged.ktx2");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("damaged.ktx2: mip level 0: the Zstandard data is damaged"),
            std::string::npos)
      << bad.error();
  std::vector<std::uint8_t> claims = packed;
  ByteWriter patch;
  patch.u64(texture.levels[0].data.size() * 4);
  std::copy(patch.data().begin(), patch.data().end(), claims.begin() + 96);
  bad = decodeKtx2(claims, "claims.ktx2");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("mip level 0 holds 8192 bytes"), std::string::npos) << bad.error();
  // Saving a DDS with a Zstandard level is refused: DDS has no supercompression.
  const std::string dds = test::scratchFolder() + "/zstd.dds";
  const Status saved = saveCompressedTexture(texture, dds, 3);
  ASSERT_FALSE(saved.ok());
  EXPECT_NE(saved.error().find("KTX2 feature"), std::string::npos);
}

// --- Hostile files ---------------------------------------------------------------------------

TEST(TextureFileHostileTest, EveryTruncationIsAnErrorNotACrash) {
  for (TextureContainer container : {TextureContainer::Dds, TextureContainer::Ktx2}) {
    const CompressedTexture texture = compressed(TextureFormat::Bc3, 16, 8, true);
    const std::vector<std::uint8_t> whole =
        container == TextureContainer::Dds ? encodeDds(texture).value() : encodeKtx2(texture);
    for (std::size_t length = 0; length < whole.size(); ++length) {
      const std::vector<std::uint8_t> cut(whole.begin(), whole.begin() + std::ptrdiff_t(length));
      const Result<CompressedTexture> result = container == TextureContainer::Dds
                                                   ? decodeDds(cut, "cut.dds")
                                                   : decodeKtx2(cut, "cut.ktx2");
      ASSERT_FALSE(result.ok()) << "accepted a file cut to " << length << " bytes";
      EXPECT_EQ(result.error().rfind("cut.", 0), 0u) << result.error();  // names the file
    }
  }
}

TEST(TextureFileHostileTest, WrongSizesAndEnormousDimensionsAreRefused) {
  const CompressedTexture texture = compressed(TextureFormat::Bc1, 16, 8, true);
  const std::vector<std::uint8_t> dds = encodeDds(texture).value();
  const std::vector<std::uint8_t> ktx = encodeKtx2(texture);
  const auto patched = [](std::vector<std::uint8_t> bytes, std::size_t at, std::uint64_t value,
                          int width) {
    for (int i = 0; i < width; ++i)
      bytes[at + std::size_t(i)] = std::uint8_t(value >> (8 * i));
    return bytes;
  };
  struct Case {
    const char* what;
    std::vector<std::uint8_t> bytes;
    bool ktx;
    const char* message;
  };
  const Case cases[] = {
      {"DDS 2^30 wide", patched(dds, 16, 1u << 30, 4), false, "outside"},
      {"DDS zero height", patched(dds, 12, 0, 4), false, "outside"},
      {"DDS 40 levels", patched(dds, 28, 40, 4), false, "mip levels"},
      {"DDS unknown FourCC", patched(dds, 84, makeFourCC('B', 'C', '7', 'X'), 4), false, "FourCC"},
      {"DDS wide enough to need more data", patched(dds, 16, 4096, 4), false, "ends inside"},
      {"KTX2 4 billion wide", patched(ktx, 20, 0xFFFFFFFFu, 4), true, "outside"},
      {"KTX2 40 levels", patched(ktx, 40, 40, 4), true, "mip levels"},
      {"KTX2 level 0 too short", patched(ktx, 88, 8, 8), true, "holds 8 bytes"},
      {"KTX2 level 0 past the end", patched(ktx, 80, ~std::uint64_t(0) - 4, 8), true,
       "outside the file"},
      {"KTX2 descriptor past the end", patched(ktx, 52, 0x7FFFFFFF, 4), true, "descriptor"},
      {"KTX2 unknown vkFormat", patched(ktx, 12, 37, 4), true, "vkFormat"},
      {"KTX2 Zstandard flag on raw levels", patched(ktx, 44, 2, 4), true,
       "Zstandard data is damaged"},
      {"KTX2 BasisLZ", patched(ktx, 44, 1, 4), true, "supercompression scheme 1"},
      {"KTX2 a cube map", patched(ktx, 36, 6, 4), true, "2D"},
  };
  for (const Case& c : cases) {
    const Result<CompressedTexture> result =
        c.ktx ? decodeKtx2(c.bytes, "bad.ktx2") : decodeDds(c.bytes, "bad.dds");
    ASSERT_FALSE(result.ok()) << c.what;
    EXPECT_NE(result.error().find(c.message), std::string::npos)
        << c.what << ": " << result.error();
  }
  // KTX2 levelCount 0 means "the base level only" (KTX 2.0, section 3.7), not an error.
  Result<CompressedTexture> base = decodeKtx2(patched(ktx, 40, 0, 4), "zero.ktx2");
  ASSERT_TRUE(base.ok()) << base.error();
  EXPECT_EQ(base->levels.size(), 1u);
}

TEST(TextureFileHostileTest, SavingFailsCleanlyAndLoadingNamesTheFile) {
  const std::string folder = test::scratchFolder();
  const CompressedTexture texture = compressed(TextureFormat::Bc1, 8, 8, false);
  EXPECT_FALSE(saveCompressedTexture(texture, folder + "/missing/folder/x.dds").ok());
  EXPECT_FALSE(saveCompressedTexture(texture, folder + "/x.png").ok());
  // A failed save leaves the old file as it was.
  const std::string path = folder + "/kept.dds";
  ASSERT_TRUE(saveCompressedTexture(texture, path).ok());
  const auto before = std::filesystem::file_size(path);
  EXPECT_FALSE(saveCompressedTexture(compressed(TextureFormat::Etc1, 8, 8, false), path).ok());
  EXPECT_EQ(std::filesystem::file_size(path), before);
  writeBytes(folder + "/garbage.ktx2", {1, 2, 3});
  Result<CompressedTexture> garbage = loadCompressedTexture(folder + "/garbage.ktx2");
  ASSERT_FALSE(garbage.ok());
  EXPECT_NE(garbage.error().find("garbage.ktx2"), std::string::npos);
  EXPECT_FALSE(loadCompressedTexture(folder + "/absent.dds").ok());
}

}  // namespace
}  // namespace relief::core
