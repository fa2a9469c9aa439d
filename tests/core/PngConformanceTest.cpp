// Every PNG colour type and bit depth the specification allows (grey 1/2/4/8/16, palette 1/2/4/8
// with and without tRNS, grey and alpha, RGB, RGBA, Adam7 interlacing, gAMA/sRGB/iCCP chunks),
// written by independent writers (Pillow, ImageMagick) and decoded by Pillow as the reference:
// Relief reads each to the same values. Damaged files (a wrong CRC, a cut IDAT, a palette index
// past the palette) are refused with a message naming the file and the problem. The header
// (size, channels, bit depth, colour space), read by Relief's own code, matches OpenImageIO's
// reading of the same file, and the streaming check of the pixel data (PngVerify) agrees with
// the decoder on every valid and every damaged file.
#include "core/image/ImageIO.h"
#include "support/ImageCompare.h"
#include "support/TestPaths.h"

#include <OpenImageIO/imageio.h>

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
  std::string name;
  int width = 0, height = 0, channels = 0;
  std::string broken;  // what is wrong with it, or empty for a valid file
};

// Runs tests/core/png_conformance.py, which writes the files and Pillow's decoding of each.
std::vector<Variant> writeVariants(const std::string& folder) {
  QProcess python;
  python.start("/usr/bin/python3",
               {QString::fromStdString(test::sourcePath("tests/core/png_conformance.py")),
                QString::fromStdString(folder)});
  EXPECT_TRUE(python.waitForFinished(120000));
  EXPECT_EQ(python.exitCode(), 0) << python.readAllStandardError().toStdString()
                                  << " (needs python3-pil and imagemagick: tools/install-deps.sh)";
  std::vector<Variant> variants;
  std::istringstream lines(python.readAllStandardOutput().toStdString());
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    Variant variant;
    words >> variant.name;
    std::string second;
    words >> second;
    if (second == "broken") {
      std::getline(words >> std::ws, variant.broken);
    } else {
      variant.width = std::stoi(second);
      words >> variant.height >> variant.channels;
    }
    variants.push_back(variant);
  }
  return variants;
}

TEST(PngConformance, EveryColourTypeAndDepthReadsAsPillowReadsIt) {
  const std::string folder = test::scratchFolder();
  const std::vector<Variant> variants = writeVariants(folder);
  int valid = 0, refused = 0;
  for (const Variant& variant : variants) {
    const std::string path = folder + "/" + variant.name + ".png";
    const Result<Image> image = loadImage(path);
    if (!variant.broken.empty()) {
      ++refused;
      ASSERT_FALSE(image.ok()) << variant.name << " (" << variant.broken << ") was read";
      EXPECT_NE(image.error().find(path), std::string::npos) << image.error();
      continue;
    }
    ++valid;
    ASSERT_TRUE(image.ok()) << variant.name << ": " << image.error();
    ASSERT_EQ(image->width(), variant.width) << variant.name;
    ASSERT_EQ(image->height(), variant.height) << variant.name;
    ASSERT_EQ(image->channels(), variant.channels) << variant.name;
    // Both sides divide the same integers by 255 or 65535 in floating point.
    EXPECT_LE(test::worstDifference(image.value(),
                                    test::readFloat32File(folder + "/" + variant.name + ".f32")),
              1e-6)
        << variant.name;
  }
  EXPECT_GE(valid, 20);
  EXPECT_EQ(refused, 3);
}

// The messages say what is wrong, not only that something is.
TEST(PngConformance, DamagedFilesAreRefusedWithTheReason) {
  const std::string folder = test::scratchFolder();
  writeVariants(folder);
  const Result<Image> index = loadImage(folder + "/broken-index.png");
  ASSERT_FALSE(index.ok());
  EXPECT_NE(index.error().find("palette index 3; the palette has 2 entries"), std::string::npos)
      << index.error();
  const Result<Image> crc = loadImage(folder + "/broken-crc.png");
  ASSERT_FALSE(crc.ok());
  EXPECT_NE(crc.error().find("CRC"), std::string::npos) << crc.error();
  const Result<Image> cut = loadImage(folder + "/broken-truncated.png");
  ASSERT_FALSE(cut.ok());
  EXPECT_NE(cut.error().find("truncated"), std::string::npos) << cut.error();
}

// OpenImageIO is the reference for the header: Relief read PNG headers through it before it had
// its own reader, and the maps artists saved since must keep their colour space.
TEST(PngConformance, HeadersReadAsOpenImageIOReadsThem) {
  const std::string folder = test::scratchFolder();
  int linear = 0, srgb = 0;
  for (const Variant& variant : writeVariants(folder)) {
    if (!variant.broken.empty())
      continue;
    const std::string path = folder + "/" + variant.name + ".png";
    const Result<ImageFileInfo> ours = readImageInfo(path);
    ASSERT_TRUE(ours.ok()) << variant.name << ": " << ours.error();
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input) << variant.name;
    const OIIO::ImageSpec& spec = input->spec();
    EXPECT_EQ(ours->width, spec.width) << variant.name;
    EXPECT_EQ(ours->height, spec.height) << variant.name;
    EXPECT_EQ(ours->channels, spec.nchannels) << variant.name;
    EXPECT_EQ(ours->bitsPerChannel, int(spec.format.size() * 8)) << variant.name;
    EXPECT_EQ(ours->formatName, "png");
    const ColorSpace theirs = colorSpaceFromOiioName(spec.get_string_attribute("oiio:ColorSpace"));
    EXPECT_EQ(ours->colorSpace, theirs)
        << variant.name << ": OpenImageIO says " << spec.get_string_attribute("oiio:ColorSpace");
    (ours->colorSpace == ColorSpace::Linear ? linear : srgb) += 1;
    const Result<Image> image = loadImage(path);
    ASSERT_TRUE(image.ok()) << image.error();
    EXPECT_EQ(image->colorSpace(), ours->colorSpace) << variant.name;
    EXPECT_EQ(image->sourceBitsPerChannel(), ours->bitsPerChannel) << variant.name;
  }
  // Both answers occur, so agreeing means something.
  EXPECT_GE(linear, 4);
  EXPECT_GE(srgb, 10);
}

TEST(PngConformance, TheStreamingCheckAgreesWithTheDecoder) {
  const std::string folder = test::scratchFolder();
  for (const Variant& variant : writeVariants(folder)) {
    const std::string path = folder + "/" + variant.name + ".png";
    const Status verified = verifyImageData(path);
    if (variant.broken.empty()) {
      EXPECT_TRUE(verified.ok()) << variant.name << ": " << verified.error();
    } else {
      ASSERT_FALSE(verified.ok()) << variant.name << " (" << variant.broken << ") passed";
      EXPECT_NE(verified.error().find(path), std::string::npos) << verified.error();
    }
  }
  const Status index = verifyImageData(folder + "/broken-index.png");
  EXPECT_NE(index.error().find("palette index 3; the palette has 2 entries"), std::string::npos)
      << index.error();
}

}  // namespace
}  // namespace relief::core
