// Image files: exact round trips for the lossless precisions, bounded reads of hostile files.
#include "core/image/ImageIO.h"
#include "core/image/PngWriter.h"
#include "support/TestPaths.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <vector>

namespace relief::core {
namespace {

using test::scratchFolder;

// A deterministic image whose values are exactly representable at `levels` steps.
Image quantizedPattern(int width, int height, int channels, int levels) {
  Image image(width, height, channels);
  std::uint32_t state = 12345u;
  for (std::size_t i = 0; i < image.valueCount(); ++i) {
    state = state * 1664525u + 1013904223u;
    image.data()[i] = float((state >> 8) % std::uint32_t(levels + 1)) / float(levels);
  }
  return image;
}

// Every stored integer level comes back (float k/levels may differ from OpenImageIO's
// conversion in the last bit, so levels are compared, not floats), and a second save of the
// loaded image reproduces the first load bit for bit.
void expectLevelsRoundTrip(const Image& original, const std::string& path, SampleFormat format,
                           int levels) {
  ASSERT_TRUE(saveImage(original, path, format).ok()) << path;
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  ASSERT_EQ(loaded->valueCount(), original.valueCount()) << path;
  for (std::size_t i = 0; i < original.valueCount(); ++i) {
    ASSERT_EQ(std::lround(loaded->data()[i] * float(levels)),
              std::lround(original.data()[i] * float(levels)))
        << path << " value " << i;
  }
  ASSERT_TRUE(saveImage(loaded.value(), path, format).ok()) << path;
  Result<Image> reloaded = loadImage(path);
  ASSERT_TRUE(reloaded.ok()) << reloaded.error();
  EXPECT_EQ(reloaded.value(), loaded.value()) << path;
}

// Relief's own PNG writer (PngWriter.h) read back by libpng through OpenImageIO, an independent
// decoder: every channel count at 8 and 16 bits, odd sizes, and images of many strips (the
// writer joins one deflate stream per strip; a wrong join or Adler-32 fails libpng's checks).
TEST(ImageIO, OurPngWriterRoundTripsThroughLibpng) {
  for (int bits : {8, 16}) {
    const int levels = bits == 8 ? 255 : 65535;
    for (int channels = 1; channels <= 4; ++channels) {
      // 37x19 is one strip; 700x900 (up to 5 MB of samples) is several.
      for (auto [width, height] : {std::pair{37, 19}, std::pair{700, 900}}) {
        const Image original = quantizedPattern(width, height, channels, levels);
        const std::string path = scratchFolder() + "/ours" + std::to_string(bits) + "_" +
                                 std::to_string(channels) + "_" + std::to_string(width) + ".png";
        PngWriteOptions options;
        options.bitsPerChannel = bits;
        ASSERT_TRUE(writePng(original, path, options).ok()) << path;
        // Straight alpha as written (OpenImageIO would otherwise premultiply it on reading).
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        OIIO::ImageBuf read(path, 0, 0, nullptr, &config);
        ASSERT_TRUE(read.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << read.geterror();
        ASSERT_EQ(read.spec().nchannels, channels);
        ASSERT_EQ(read.nativespec().format,
                  bits == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
        std::vector<float> pixels(original.valueCount());
        ASSERT_TRUE(read.get_pixels(read.roi(), OIIO::TypeDesc::FLOAT, pixels.data()));
        for (std::size_t i = 0; i < original.valueCount(); ++i) {
          ASSERT_EQ(std::lround(pixels[i] * float(levels)),
                    std::lround(original.data()[i] * float(levels)))
              << path << " value " << i;
        }
      }
    }
  }
}

// Alpha is data (a height packed beside a normal), kept as stored: colour above the alpha and
// colour under zero alpha come back, in every file type that has alpha. (OpenImageIO alone
// divides colour by alpha when writing PNG and multiplies when reading: 0.8 under alpha 0.5
// came back as 0.5.)
TEST(ImageIO, AlphaIsKeptStraightInEveryFileType) {
  Image image(3, 1, 4);
  const float values[12] = {0.8f, 0.6f,  0.4f, 0.5f, 0.2f, 0.4f,
                            0.6f, 0.25f, 0.7f, 0.3f, 0.9f, 0.0f};
  std::copy(values, values + 12, image.data());
  for (const char* name : {"/alpha.png", "/alpha.tga", "/alpha.tif", "/alpha.exr"}) {
    const std::string path = scratchFolder() + name;
    ASSERT_TRUE(saveImage(image, path, SampleFormat::UInt8).ok()) << name;
    Result<Image> loaded = loadImage(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    for (int i = 0; i < 12; ++i)
      EXPECT_NEAR(loaded->data()[i], values[i], 0.5f / 255.0f + 1e-6f) << name << " value " << i;
  }
}

// The colour space travels in the file (sRGB chunk or gAMA 1.0, and OpenImageIO's text tag).
TEST(ImageIO, OurPngWriterRecordsTheColourSpace) {
  for (ColorSpace space : {ColorSpace::Srgb, ColorSpace::Linear}) {
    Image image = quantizedPattern(8, 8, 3, 255);
    image.setColorSpace(space);
    const std::string path = scratchFolder() + "/space.png";
    ASSERT_TRUE(saveImage(image, path, SampleFormat::UInt8).ok());
    Result<Image> loaded = loadImage(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    EXPECT_EQ(loaded->colorSpace(), space);
  }
}

// 8-bit saves of finer data are dithered: a value between two levels comes back as a mix of
// both whose mean is the value (within 0.05 of a level over 64x64 texels), not as bands of the
// nearer level; and no texel moves more than one level.
TEST(ImageIO, EightBitPngSavesOfFinerDataAreDithered) {
  const float value = (100.0f + 0.3f) / 255.0f;
  Image image(64, 64, 1);
  std::fill(image.data(), image.data() + image.valueCount(), value);
  image.setSourceBitsPerChannel(16);
  const std::string path = scratchFolder() + "/dither.png";
  ASSERT_TRUE(saveImage(image, path, SampleFormat::UInt8).ok());
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  double sum = 0.0;
  for (std::size_t i = 0; i < loaded->valueCount(); ++i) {
    const float level = loaded->data()[i] * 255.0f;
    EXPECT_TRUE(std::lround(level) == 100 || std::lround(level) == 101) << level;
    sum += double(level);
  }
  EXPECT_NEAR(sum / double(loaded->valueCount()), 100.3, 0.05);
}

TEST(ImageIO, SixteenBitPngRoundTripsExactly) {
  const Image original = quantizedPattern(37, 19, 3, 65535);
  const std::string path = scratchFolder() + "/round16.png";
  expectLevelsRoundTrip(original, path, SampleFormat::UInt16, 65535);
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(loaded->sourceBitsPerChannel(), 16);
  // Auto keeps a 16-bit source 16-bit.
  ASSERT_TRUE(saveImage(loaded.value(), path).ok());
  EXPECT_EQ(readImageInfo(path)->bitsPerChannel, 16);
}

TEST(ImageIO, SixteenBitTiffRoundTripsExactly) {
  expectLevelsRoundTrip(quantizedPattern(17, 23, 4, 65535), scratchFolder() + "/round16.tif",
                        SampleFormat::UInt16, 65535);
}

TEST(ImageIO, FloatExrRoundTripsExactly) {
  Image original(16, 9, 4);
  for (std::size_t i = 0; i < original.valueCount(); ++i) {
    // Values outside [0, 1], negative, tiny and with full mantissas.
    original.data()[i] = std::sin(float(i) * 1.37f) * 1000.0f + 1e-7f * float(i);
  }
  const std::string path = scratchFolder() + "/roundfloat.exr";
  ASSERT_TRUE(saveImage(original, path, SampleFormat::Float).ok());
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->colorSpace(), ColorSpace::Linear);
  for (std::size_t i = 0; i < original.valueCount(); ++i) {
    ASSERT_EQ(loaded->data()[i], original.data()[i]) << "value " << i;
  }
}

TEST(ImageIO, HalfExrKeepsHalfPrecisionValues) {
  // Multiples of 1/1024 in [0, 2) are exact in half precision (10-bit mantissa).
  const Image original = quantizedPattern(8, 8, 1, 1024);
  const std::string path = scratchFolder() + "/roundhalf.exr";
  ASSERT_TRUE(saveImage(original, path, SampleFormat::Half).ok());
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded.value(), original);
}

TEST(ImageIO, EightBitFormatsKeepEightBitValues) {
  const Image original = quantizedPattern(21, 13, 3, 255);
  for (const char* extension : {".png", ".tga", ".tif"}) {
    expectLevelsRoundTrip(original, scratchFolder() + "/round8" + extension, SampleFormat::UInt8,
                          255);
  }
}

TEST(ImageIO, JpegIsCloseOnSmoothContent) {
  // JPEG is lossy; on a smooth gradient it should stay within a few levels.
  Image original(64, 64, 3, ColorSpace::Srgb);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      original.at(x, y, 0) = float(x) / 63.0f;
      original.at(x, y, 1) = float(y) / 63.0f;
      original.at(x, y, 2) = 0.5f;
    }
  }
  const std::string path = scratchFolder() + "/smooth.jpg";
  ASSERT_TRUE(saveImage(original, path).ok());
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->colorSpace(), ColorSpace::Srgb);
  double worst = 0.0;
  for (std::size_t i = 0; i < original.valueCount(); ++i) {
    worst = std::max(worst, double(std::abs(loaded->data()[i] - original.data()[i])));
  }
  EXPECT_LT(worst, 8.0 / 255.0);
}

TEST(ImageIO, EightBitOutputOfFinerDataIsDithered) {
  // A gentle gradient spanning 4 levels over 256 texels: rounded, it would be 4 flat bands.
  Image gradient(256, 16, 1);
  gradient.setSourceBitsPerChannel(32);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 256; ++x)
      gradient.at(x, y, 0) = (100.0f + 4.0f * x / 256.0f) / 255.0f;
  }
  const std::string path = scratchFolder() + "/dithered.png";
  ASSERT_TRUE(saveImage(gradient, path, SampleFormat::UInt8).ok());
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok());
  // Each column keeps its mean (within the noise of 16 samples) instead of snapping to a band,
  // and no value strays more than one level.
  int columnsBetweenLevels = 0;
  for (int x = 0; x < 256; ++x) {
    double mean = 0.0;
    for (int y = 0; y < 16; ++y) {
      const double level = loaded->at(x, y, 0) * 255.0;
      ASSERT_LE(std::abs(level - gradient.at(x, y, 0) * 255.0), 1.0 + 1e-3);
      mean += level / 16.0;
    }
    columnsBetweenLevels += std::abs(mean - std::round(mean)) > 0.05;
  }
  EXPECT_GT(columnsBetweenLevels, 128);
}

TEST(ImageIO, InfoReportsWhatTheHeaderSays) {
  const std::string path = scratchFolder() + "/info16.png";
  ASSERT_TRUE(saveImage(quantizedPattern(30, 20, 1, 65535), path, SampleFormat::UInt16).ok());
  Result<ImageFileInfo> info = readImageInfo(path);
  ASSERT_TRUE(info.ok()) << info.error();
  EXPECT_EQ(info->width, 30);
  EXPECT_EQ(info->height, 20);
  EXPECT_EQ(info->channels, 1);
  EXPECT_EQ(info->bitsPerChannel, 16);
  EXPECT_FALSE(info->isFloat);
  EXPECT_EQ(info->formatName, "png");
}

// A PNG signature and an IHDR chunk claiming the given size, with a correct CRC, followed by
// an empty IDAT and IEND: a header that lies about an enormous image.
std::vector<unsigned char> pngHeaderClaiming(std::uint32_t width, std::uint32_t height) {
  std::vector<unsigned char> bytes = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  auto crc32 = [](const unsigned char* data, std::size_t size) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) {
      crc ^= data[i];
      for (int bit = 0; bit < 8; ++bit)
        crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
  };
  auto put32 = [](std::vector<unsigned char>& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8)
      out.push_back((unsigned char)(value >> shift));
  };
  auto chunk = [&](const char* type, const std::vector<unsigned char>& data) {
    put32(bytes, std::uint32_t(data.size()));
    std::vector<unsigned char> typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    bytes.insert(bytes.end(), typed.begin(), typed.end());
    put32(bytes, crc32(typed.data(), typed.size()));
  };
  std::vector<unsigned char> ihdr;
  put32(ihdr, width);
  put32(ihdr, height);
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8-bit RGB, deflate, no filter, no interlace
  chunk("IHDR", ihdr);
  chunk("IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});
  chunk("IEND", {});
  return bytes;
}

void writeBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// Writes `image` tiled (tile x tile texels), as VFX pipelines write TIFF and EXR; with `mipmap`
// as a mip-mapped texture made by OpenImageIO's maketx (what texture pipelines hand artists).
void writeTiled(const Image& image, const std::string& path, OIIO::TypeDesc type, int tile,
                bool mipmap) {
  OIIO::ImageSpec spec(image.width(), image.height(), image.channels(), type);
  spec.tile_width = spec.tile_height = tile;
  if (mipmap) {
    OIIO::ImageBuf buffer(
        OIIO::ImageSpec(image.width(), image.height(), image.channels(), OIIO::TypeDesc::FLOAT),
        const_cast<float*>(image.data()));
    OIIO::ImageSpec config;
    config.tile_width = config.tile_height = tile;
    config.format = type;
    ASSERT_TRUE(
        OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, buffer, path, config))
        << OIIO::geterror();
    return;
  }
  auto output = OIIO::ImageOutput::create(path);
  ASSERT_TRUE(output) << path;
  ASSERT_TRUE(output->open(path, spec)) << output->geterror();
  ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, image.data())) << output->geterror();
  ASSERT_TRUE(output->close());
}

// Tiled files used to crash the data check (SIGFPE inside OpenImageIO's scanline reader). Sizes
// that are not multiples of the tile size leave partial edge tiles, the case most easily wrong.
TEST(ImageIO, TiledTiffAndMipMappedExrVerifyAndLoadExactly) {
  const Image pattern = quantizedPattern(250, 130, 3, 1024);  // exact in half and float
  const std::string folder = scratchFolder();
  struct Case {
    std::string name;
    OIIO::TypeDesc type;
    bool mipmap;
  };
  for (const Case& c : {Case{"tiled.tif", OIIO::TypeDesc::FLOAT, false},
                        Case{"tiled16.tif", OIIO::TypeDesc::UINT16, false},
                        Case{"tiled_mip.exr", OIIO::TypeDesc::HALF, true}}) {
    const std::string path = folder + "/" + c.name;
    writeTiled(pattern, path, c.type, 64, c.mipmap);
    const Status verified = verifyImageData(path);
    EXPECT_TRUE(verified.ok()) << verified.error();
    Result<Image> loaded = loadImage(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error();
    ASSERT_EQ(loaded->width(), 250) << c.name;  // the top level, not a smaller one
    ASSERT_EQ(loaded->height(), 130) << c.name;
    for (std::size_t i = 0; i < pattern.valueCount(); ++i) {
      ASSERT_EQ(std::lround(loaded->data()[i] * 1024.0f), std::lround(pattern.data()[i] * 1024.0f))
          << c.name << " value " << i;
    }
  }
}

TEST(ImageIO, RefusesEnormousHeaderBeforeAllocating) {
  const std::string path = scratchFolder() + "/huge.png";
  writeBytes(path, pngHeaderClaiming(100000, 100000));
  // 100000^2 RGB floats would be 120 GB; the refusal must come from the header check.
  Result<Image> loaded = loadImage(path);
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().find("huge.png"), std::string::npos) << loaded.error();
  EXPECT_NE(loaded.error().find("100000x100000"), std::string::npos) << loaded.error();
  EXPECT_FALSE(readImageInfo(path).ok());
}

TEST(ImageIO, ClearErrorsForMissingEmptyAndNonImageFiles) {
  Result<Image> missing = loadImage(scratchFolder() + "/does-not-exist.png");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("does-not-exist.png: file not found"), std::string::npos);

  const std::string empty = scratchFolder() + "/empty.png";
  writeBytes(empty, {});
  Result<Image> emptyResult = loadImage(empty);
  ASSERT_FALSE(emptyResult.ok());
  EXPECT_NE(emptyResult.error().find("empty.png: the file is empty"), std::string::npos);

  const std::string text = scratchFolder() + "/notes.png";
  writeBytes(text, {'h', 'e', 'l', 'l', 'o', '\n'});
  Result<Image> textResult = loadImage(text);
  ASSERT_FALSE(textResult.ok());
  EXPECT_NE(textResult.error().find("notes.png"), std::string::npos) << textResult.error();
}

TEST(ImageIO, TruncatedFilesAreDetectedByLoadAndVerify) {
  const std::string whole = scratchFolder() + "/whole.png";
  ASSERT_TRUE(saveImage(quantizedPattern(256, 256, 3, 255), whole, SampleFormat::UInt8).ok());
  EXPECT_TRUE(verifyImageData(whole).ok());
  std::ifstream in(whole, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), {});
  const std::string cut = scratchFolder() + "/cut.png";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  // The last chunk ends past the file's end: refused from the chunk headers already, before
  // libpng reads it (core/image/PngPreflight), by every entry point.
  const Result<ImageFileInfo> info = readImageInfo(cut);
  ASSERT_FALSE(info.ok());
  EXPECT_NE(info.error().find("cut.png: the PNG is truncated"), std::string::npos) << info.error();
  Status verified = verifyImageData(cut);
  ASSERT_FALSE(verified.ok());
  EXPECT_NE(verified.error().find("cut.png"), std::string::npos);
  EXPECT_FALSE(loadImage(cut).ok());
}

TEST(ImageIO, FailedSaveLeavesNoFileAndNamesThePath) {
  const std::string path = scratchFolder() + "/no/such/folder/out.png";
  Status saved = saveImage(quantizedPattern(4, 4, 3, 255), path);
  ASSERT_FALSE(saved.ok());
  EXPECT_NE(saved.error().find("out.png"), std::string::npos);
}

TEST(ImageIO, AFailedSaveLeavesThePreviousFileAsItWas) {
  const std::string folder = scratchFolder();
  for (const char* name : {"/keep.png", "/keep.exr", "/keep.tif"}) {
    const std::string path = folder + name;
    ASSERT_TRUE(saveImage(quantizedPattern(16, 16, 3, 255), path, SampleFormat::UInt8).ok());
    std::ifstream in(path, std::ios::binary);
    const std::string before((std::istreambuf_iterator<char>(in)), {});
    // Writes beyond 4 KB fail, as on a full disk. SIGXFSZ keeps its default action (kill the
    // process): saveImage itself must keep it from ending the program.
    rlimit original{};
    getrlimit(RLIMIT_FSIZE, &original);
    rlimit tiny = original;
    tiny.rlim_cur = 4096;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &tiny), 0);
    Status saved = saveImage(quantizedPattern(512, 512, 4, 65535), path, SampleFormat::UInt16);
    setrlimit(RLIMIT_FSIZE, &original);
    EXPECT_FALSE(saved.ok()) << name;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
      EXPECT_EQ(entry.path().filename().string().find(".saving"), std::string::npos)
          << "temporary file left: " << entry.path();
    std::ifstream again(path, std::ios::binary);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(again)), {}), before) << name;
  }
}

TEST(ImageIO, SaveReplacesAnExistingFile) {
  const std::string path = scratchFolder() + "/replace.png";
  ASSERT_TRUE(saveImage(quantizedPattern(4, 4, 3, 255), path, SampleFormat::UInt8).ok());
  const Image second = quantizedPattern(8, 2, 1, 255);
  ASSERT_TRUE(saveImage(second, path, SampleFormat::UInt8).ok());
  Result<Image> loaded = loadImage(path);
  ASSERT_TRUE(loaded.ok());
  EXPECT_EQ(loaded->width(), 8);
  EXPECT_EQ(loaded->channels(), 1);
}

}  // namespace
}  // namespace relief::core
