// The image types besides PNG, as artists' tools write them: JPEG (baseline 4:2:0 and 4:4:4,
// progressive, optimised Huffman tables, grey, Adobe CMYK), TGA (uncompressed and run-length,
// grey, RGB, RGBA, colour-mapped, both row orders), TIFF (strips with no, LZW, deflate and
// PackBits compression, tiles, 1/8/16-bit grey, 16-bit RGB, 32-bit float, palette, a plane per
// channel) written by Pillow and ImageMagick and decoded by them as the reference
// (tests/core/image_conformance.py); OpenEXR (scanline and tiled, mip-mapped, half and float,
// every lossless compression, one channel, multi-part) written here through OpenEXR's own
// library, whose stored halves and floats are the reference. Relief reads each to the same
// values (TIFF palettes within one level in 255: OpenImageIO's rounding, see the script); of a
// multi-part EXR or a multi-page TIFF it reads the first part and says so. A bilevel TIFF
// without its BitsPerSample tag, which OpenImageIO misreads, is refused with the reason.
#include "core/image/ImageIO.h"
#include "support/ImageCompare.h"
#include "support/TestPaths.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfRgbaFile.h>
#include <ImfTiledRgbaFile.h>

#include <QProcess>
#include <QString>
#include <QStringList>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace relief::core {
namespace {

struct Variant {
  std::string file;
  int width = 0, height = 0, channels = 0;
  double tolerance = 0.0;
  std::string refusedFor;  // what the message must name, for a file Relief refuses
};

// Runs tests/core/image_conformance.py, which writes the files and the reference decodings.
std::vector<Variant> writeVariants(const std::string& folder) {
  QProcess python;
  python.start("/usr/bin/python3",
               {QString::fromStdString(test::sourcePath("tests/core/image_conformance.py")),
                QString::fromStdString(folder)});
  EXPECT_TRUE(python.waitForFinished(120000));
  EXPECT_EQ(python.exitCode(), 0) << python.readAllStandardError().toStdString()
                                  << " (needs python3-pil and imagemagick: tools/install-deps.sh)";
  std::vector<Variant> variants;
  std::istringstream lines(python.readAllStandardOutput().toStdString());
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    Variant variant;
    std::string second;
    words >> variant.file >> second;
    if (second == "refused") {
      words >> variant.refusedFor;
    } else {
      variant.width = std::stoi(second);
      words >> variant.height >> variant.channels >> variant.tolerance;
    }
    variants.push_back(variant);
  }
  return variants;
}

TEST(ImageConformance, JpegTgaAndTiffReadAsTheirIndependentDecodersReadThem) {
  const std::string folder = test::scratchFolder();
  const std::vector<Variant> variants = writeVariants(folder);
  int jpeg = 0, tga = 0, tiff = 0, refused = 0;
  for (const Variant& variant : variants) {
    SCOPED_TRACE(variant.file);
    const std::string path = folder + "/" + variant.file;
    const Result<Image> image = loadImage(path);
    if (!variant.refusedFor.empty()) {
      ++refused;
      ASSERT_FALSE(image.ok()) << "read, though OpenImageIO misreads it";
      EXPECT_NE(image.error().find(path), std::string::npos) << image.error();
      EXPECT_NE(image.error().find(variant.refusedFor), std::string::npos) << image.error();
      EXPECT_FALSE(readImageInfo(path).ok());
      continue;
    }
    ASSERT_TRUE(image.ok()) << image.error();
    EXPECT_EQ(image->width(), variant.width);
    EXPECT_EQ(image->height(), variant.height);
    ASSERT_EQ(image->channels(), variant.channels);
    const std::string stem = variant.file.substr(0, variant.file.rfind('.'));
    EXPECT_LE(
        test::worstDifference(image.value(), test::readFloat32File(folder + "/" + stem + ".f32")),
        variant.tolerance + 1e-6);
    // The header agrees with the pixels, and the streaming check passes the file.
    const Result<ImageFileInfo> info = readImageInfo(path);
    ASSERT_TRUE(info.ok()) << info.error();
    EXPECT_EQ(info->channels, variant.channels);
    EXPECT_EQ(info->subimages, stem == "tiff-pages" ? 2 : 1);
    if (stem.find("palette") != std::string::npos) {
      EXPECT_EQ(info->bitsPerChannel, 8) << "a palette's entries hold 8 bits a channel";
    }
    const Status intact = verifyImageData(path);
    EXPECT_TRUE(intact.ok()) << intact.error();
    jpeg += stem.starts_with("jpeg") ? 1 : 0;
    tga += stem.starts_with("tga") ? 1 : 0;
    tiff += stem.starts_with("tiff") ? 1 : 0;
  }
  EXPECT_GE(jpeg, 7);
  EXPECT_GE(tga, 11);
  EXPECT_GE(tiff, 15);
  EXPECT_EQ(refused, 1);
}

// Texels an EXR holds: negative, above one, and fine steps, as sculpted height maps have.
float exrValue(int x, int y, int c) {
  return float((x * 7 + y * 13 + c * 29) % 97 - 20) / 8.0f + float(c) / 64.0f;
}

constexpr int kExrWidth = 45, kExrHeight = 29;  // no tile or 16-row block ends on the edge

std::vector<Imf::Rgba> exrPixels() {
  std::vector<Imf::Rgba> pixels(std::size_t(kExrWidth) * kExrHeight);
  for (int y = 0; y < kExrHeight; ++y) {
    for (int x = 0; x < kExrWidth; ++x) {
      pixels[std::size_t(y) * kExrWidth + std::size_t(x)] =
          Imf::Rgba(half(exrValue(x, y, 0)), half(exrValue(x, y, 1)), half(exrValue(x, y, 2)),
                    half(exrValue(x, y, 3)));
    }
  }
  return pixels;
}

// What the file stores: each value rounded to half, as OpenEXR rounds it.
std::vector<float> storedHalves(int channels) {
  std::vector<float> values;
  for (int y = 0; y < kExrHeight; ++y) {
    for (int x = 0; x < kExrWidth; ++x) {
      for (int c = 0; c < channels; ++c)
        values.push_back(float(half(exrValue(x, y, c))));
    }
  }
  return values;
}

void writeScanlineRgba(const std::string& path, Imf::Compression compression) {
  const std::vector<Imf::Rgba> pixels = exrPixels();
  Imf::RgbaOutputFile file(path.c_str(), kExrWidth, kExrHeight, Imf::WRITE_RGBA, 1.0f,
                           Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y, compression);
  file.setFrameBuffer(pixels.data(), 1, kExrWidth);
  file.writePixels(kExrHeight);
}

// Tiles of 16x16 and every mip level (each level the full image, box-filtered or not, does not
// matter: Relief reads level 0).
void writeTiledMipmapped(const std::string& path) {
  const std::vector<Imf::Rgba> pixels = exrPixels();
  Imf::TiledRgbaOutputFile file(path.c_str(), kExrWidth, kExrHeight, 16, 16, Imf::MIPMAP_LEVELS,
                                Imf::ROUND_DOWN, Imf::WRITE_RGB, 1.0f, Imath::V2f(0, 0), 1.0f,
                                Imf::INCREASING_Y, Imf::ZIP_COMPRESSION);
  for (int level = 0; level < file.numLevels(); ++level) {
    const int width = file.levelWidth(level), height = file.levelHeight(level);
    std::vector<Imf::Rgba> scaled(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x)
        scaled[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
            pixels[std::size_t(y << level) * kExrWidth + std::size_t(x << level)];
    }
    file.setFrameBuffer(scaled.data(), 1, std::size_t(width));
    file.writeTiles(0, file.numXTiles(level) - 1, 0, file.numYTiles(level) - 1, level);
  }
}

// One 32-bit float channel named Y (a height map as renderers bake it).
Imf::Header floatHeightHeader(Imf::Compression compression) {
  Imf::Header header(kExrWidth, kExrHeight);
  header.compression() = compression;
  header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
  return header;
}

std::vector<float> floatHeights() {
  std::vector<float> heights;
  for (int y = 0; y < kExrHeight; ++y) {
    for (int x = 0; x < kExrWidth; ++x)
      heights.push_back(exrValue(x, y, 0) / 3.0f);  // not a half: all 32 bits count
  }
  return heights;
}

Imf::FrameBuffer heightSlice(std::vector<float>& heights) {
  Imf::FrameBuffer frame;
  frame.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(heights.data()), sizeof(float),
                               sizeof(float) * kExrWidth));
  return frame;
}

void writeFloatHeight(const std::string& path, Imf::Compression compression) {
  std::vector<float> heights = floatHeights();
  Imf::OutputFile file(path.c_str(), floatHeightHeader(compression));
  file.setFrameBuffer(heightSlice(heights));
  file.writePixels(kExrHeight);
}

// Two parts as compositors write them: the height first, then a beauty pass (RGBA halves).
void writeMultiPart(const std::string& path) {
  Imf::Header height = floatHeightHeader(Imf::ZIP_COMPRESSION);
  height.setName("height");
  height.setType(Imf::SCANLINEIMAGE);
  Imf::Header beauty(kExrWidth, kExrHeight);
  beauty.setName("beauty");
  beauty.setType(Imf::SCANLINEIMAGE);
  for (const char* name : {"R", "G", "B", "A"})
    beauty.channels().insert(name, Imf::Channel(Imf::HALF));
  std::vector<Imf::Header> headers{height, beauty};
  Imf::MultiPartOutputFile file(path.c_str(), headers.data(), int(headers.size()));
  std::vector<float> heights = floatHeights();
  Imf::OutputPart first(file, 0);
  first.setFrameBuffer(heightSlice(heights));
  first.writePixels(kExrHeight);
  std::vector<Imf::Rgba> pixels = exrPixels();
  Imf::FrameBuffer frame;
  char* base = reinterpret_cast<char*>(pixels.data());
  for (const auto& [name, offset] :
       {std::pair{"R", offsetof(Imf::Rgba, r)}, std::pair{"G", offsetof(Imf::Rgba, g)},
        std::pair{"B", offsetof(Imf::Rgba, b)}, std::pair{"A", offsetof(Imf::Rgba, a)}}) {
    frame.insert(name, Imf::Slice(Imf::HALF, base + offset, sizeof(Imf::Rgba),
                                  sizeof(Imf::Rgba) * kExrWidth));
  }
  Imf::OutputPart second(file, 1);
  second.setFrameBuffer(frame);
  second.writePixels(kExrHeight);
}

TEST(ImageConformance, ExrReadsTheStoredValuesScanlineTiledAndFloat) {
  const std::string folder = test::scratchFolder();
  struct Case {
    std::string name;
    int channels;
    std::vector<float> expected;
  };
  std::vector<Case> cases;
  for (const auto& [name, compression] :
       {std::pair{"none", Imf::NO_COMPRESSION}, std::pair{"rle", Imf::RLE_COMPRESSION},
        std::pair{"zips", Imf::ZIPS_COMPRESSION}, std::pair{"zip", Imf::ZIP_COMPRESSION},
        std::pair{"piz", Imf::PIZ_COMPRESSION}}) {
    const std::string file = std::string("rgba-") + name + ".exr";
    writeScanlineRgba(folder + "/" + file, compression);
    cases.push_back({file, 4, storedHalves(4)});
  }
  writeTiledMipmapped(folder + "/tiled-mipmapped.exr");
  cases.push_back({"tiled-mipmapped.exr", 3, storedHalves(3)});
  for (const auto& [name, compression] :
       {std::pair{"zip", Imf::ZIP_COMPRESSION}, std::pair{"piz", Imf::PIZ_COMPRESSION}}) {
    const std::string file = std::string("height-float-") + name + ".exr";
    writeFloatHeight(folder + "/" + file, compression);
    cases.push_back({file, 1, floatHeights()});
  }
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = folder + "/" + c.name;
    const Result<Image> image = loadImage(path);
    ASSERT_TRUE(image.ok()) << image.error();
    ASSERT_EQ(image->channels(), c.channels);
    // Exact: half and float widen to float without rounding.
    EXPECT_EQ(test::worstDifference(image.value(), c.expected), 0.0);
    EXPECT_EQ(image->colorSpace(), ColorSpace::Linear);
    const Result<ImageFileInfo> info = readImageInfo(path);
    ASSERT_TRUE(info.ok()) << info.error();
    EXPECT_TRUE(info->isFloat);
    EXPECT_EQ(info->subimages, 1);
    const Status intact = verifyImageData(path);
    EXPECT_TRUE(intact.ok()) << intact.error();
  }
}

// Relief reads the first part, as OpenImageIO and most tools do, and the header says how many
// there are and which one is read, so an artist who wanted another part knows to extract it.
TEST(ImageConformance, AMultiPartExrReadsItsFirstPartAndSaysSo) {
  const std::string path = test::scratchFolder() + "/passes.exr";
  writeMultiPart(path);
  const Result<Image> image = loadImage(path);
  ASSERT_TRUE(image.ok()) << image.error();
  ASSERT_EQ(image->channels(), 1);
  EXPECT_EQ(test::worstDifference(image.value(), floatHeights()), 0.0);
  const Result<ImageFileInfo> info = readImageInfo(path);
  ASSERT_TRUE(info.ok()) << info.error();
  EXPECT_EQ(info->subimages, 2);
  EXPECT_EQ(info->subimageName, "height");
  EXPECT_EQ(info->channels, 1);
}

}  // namespace
}  // namespace relief::core
