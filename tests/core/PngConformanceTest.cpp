// Every PNG colour type and bit depth the specification allows (grey 1/2/4/8/16, palette 1/2/4/8
// with and without tRNS, grey and alpha, RGB, RGBA, Adam7 interlacing, gAMA/sRGB/iCCP chunks),
// written by independent writers (Pillow, ImageMagick) and decoded by Pillow as the reference:
// Relief reads each to the same values. Damaged files (a wrong CRC, a cut IDAT, a palette index
// past the palette) are refused with a message naming the file and the problem.
#include "core/image/ImageIO.h"
#include "support/TestPaths.h"

#include <QProcess>
#include <QString>
#include <QStringList>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
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

std::vector<float> readFloats(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  std::vector<float> values(std::size_t(in.tellg()) / sizeof(float));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  return values;
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
    const std::vector<float> expected = readFloats(folder + "/" + variant.name + ".f32");
    ASSERT_EQ(expected.size(), std::size_t(variant.width * variant.height * variant.channels))
        << variant.name;
    double worst = 0.0;
    for (int y = 0; y < variant.height; ++y) {
      for (int x = 0; x < variant.width; ++x) {
        for (int c = 0; c < variant.channels; ++c) {
          const float theirs =
              expected[(std::size_t(y) * std::size_t(variant.width) + std::size_t(x)) *
                           std::size_t(variant.channels) +
                       std::size_t(c)];
          worst = std::max(worst, double(std::abs(theirs - image->at(x, y, c))));
        }
      }
    }
    // Both sides divide the same integers by 255 or 65535 in floating point.
    EXPECT_LE(worst, 1e-6) << variant.name;
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

}  // namespace
}  // namespace relief::core
