// Relief's fast PNG pixel decoder (core/image/PngReader.h) against libpng, read through
// OpenImageIO: an independent decoder of the same files. Files are written by libpng (all five
// row filters appear, which the test checks) and by hand for the damaged and unusual cases.
#include "core/image/ImageIO.h"
#include "core/image/PngReader.h"
#include "support/TestPaths.h"

#include <OpenImageIO/imageio.h>
#include <zlib.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace relief::core {
namespace {

using test::scratchFolder;

// libpng's own decoding of `path` to floats, straight from OpenImageIO (alpha kept straight, as
// Relief reads it: OpenImageIO would otherwise multiply the colour by it).
std::vector<float> decodedByLibpng(const std::string& path, int& channels) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(path, &config);
  EXPECT_TRUE(input) << path;
  if (!input)
    return {};
  const OIIO::ImageSpec& spec = input->spec();
  channels = spec.nchannels;
  std::vector<float> values(std::size_t(spec.width) * std::size_t(spec.height) *
                            std::size_t(spec.nchannels));
  EXPECT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, values.data()));
  return values;
}

// An image that makes libpng's adaptive filter choice vary by row: smooth ramps (Sub, Up,
// Average, Paeth win) and bands of noise and of flat colour (None wins).
std::vector<std::uint16_t> mixedContent(int width, int height, int channels) {
  std::vector<std::uint16_t> values(std::size_t(width) * std::size_t(height) *
                                    std::size_t(channels));
  std::uint32_t state = 7u;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < channels; ++c) {
        state = state * 1664525u + 1013904223u;
        const int band = (y / 5) % 5;
        std::uint32_t v = 0;
        if (band == 0)
          v = std::uint32_t(x * 900 + c * 5000);  // horizontal ramp
        else if (band == 1)
          v = std::uint32_t(y * 700 + c * 3000);  // vertical ramp
        else if (band == 2)
          v = state >> 16;  // noise
        else if (band == 3)
          v = std::uint32_t((x + y) * 450 + (x * y) % 97);  // diagonal
        else
          v = 40000;  // flat
        values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) +
               std::size_t(c)] = std::uint16_t(v);
      }
    }
  }
  return values;
}

std::vector<std::uint8_t> fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

void putBigEndian(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(std::uint8_t(value >> shift));
}

void appendChunk(std::vector<std::uint8_t>& png, const char* type,
                 const std::vector<std::uint8_t>& data) {
  putBigEndian(png, std::uint32_t(data.size()));
  const std::size_t start = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  putBigEndian(png, std::uint32_t(crc32(0, &png[start], uInt(data.size() + 4))));
}

// A hand-made 8-bit PNG: `filtered` is the inflated stream (each row's filter byte, then its
// bytes), compressed with zlib; `extra` chunks go before IDAT.
std::vector<std::uint8_t> handMadePng(
    int width, int height, int colourType, const std::vector<std::uint8_t>& filtered,
    const std::vector<std::pair<const char*, std::vector<std::uint8_t>>>& extra = {}) {
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  putBigEndian(header, std::uint32_t(width));
  putBigEndian(header, std::uint32_t(height));
  header.insert(header.end(), {8, std::uint8_t(colourType), 0, 0, 0});
  appendChunk(png, "IHDR", header);
  for (const auto& [type, data] : extra)
    appendChunk(png, type, data);
  uLongf size = compressBound(uLong(filtered.size()));
  std::vector<std::uint8_t> compressed(size);
  EXPECT_EQ(compress2(compressed.data(), &size, filtered.data(), uLong(filtered.size()), 9), Z_OK);
  compressed.resize(size);
  appendChunk(png, "IDAT", compressed);
  appendChunk(png, "IEND", {});
  return png;
}

// Every colour type the fast path takes, at 8 and 16 bits, decodes to libpng's floats bit for
// bit; between them the files use all five row filters (counted from their inflated streams).
TEST(PngReader, DecodesLikeLibpngForEveryChannelCountAndDepthWithEveryFilter) {
  std::array<int, 5> filtersSeen = {};
  for (int bits : {8, 16}) {
    for (int channels = 1; channels <= 4; ++channels) {
      const int width = 61, height = 53;
      const std::string path = scratchFolder() + "/libpng_" + std::to_string(bits) + "_" +
                               std::to_string(channels) + ".png";
      const std::vector<std::uint16_t> values = mixedContent(width, height, channels);
      {
        auto output = OIIO::ImageOutput::create(path);
        ASSERT_TRUE(output);
        OIIO::ImageSpec spec(width, height, channels,
                             bits == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
        spec.attribute("oiio:UnassociatedAlpha", 1);
        ASSERT_TRUE(output->open(path, spec));
        ASSERT_TRUE(output->write_image(OIIO::TypeDesc::UINT16, values.data()));
        ASSERT_TRUE(output->close());
      }
      int libpngChannels = 0;
      const std::vector<float> expected = decodedByLibpng(path, libpngChannels);
      ASSERT_EQ(libpngChannels, channels);

      Image image(width, height, channels);
      const Result<PngFastDecode> decoded = decodePngPixels(path, image);
      ASSERT_TRUE(decoded.ok()) << decoded.error();
      ASSERT_EQ(decoded.value(), PngFastDecode::Decoded) << path;
      ASSERT_EQ(image.valueCount(), expected.size());
      for (std::size_t i = 0; i < expected.size(); ++i)
        ASSERT_EQ(image.data()[i], expected[i]) << path << " value " << i;

      // loadImage takes the same path.
      const Result<Image> loaded = loadImage(path);
      ASSERT_TRUE(loaded.ok()) << loaded.error();
      ASSERT_EQ(loaded->valueCount(), image.valueCount());
      EXPECT_TRUE(std::equal(image.data(), image.data() + image.valueCount(), loaded->data()))
          << path;

      // Count the row filters libpng chose: inflate the IDAT payloads with zlib.
      const std::vector<std::uint8_t> png = fileBytes(path);
      std::vector<std::uint8_t> stream;
      for (std::size_t at = 8; at + 12 <= png.size();) {
        const std::uint32_t length = std::uint32_t(png[at]) << 24 |
                                     std::uint32_t(png[at + 1]) << 16 |
                                     std::uint32_t(png[at + 2]) << 8 | png[at + 3];
        if (std::string(png.begin() + long(at) + 4, png.begin() + long(at) + 8) == "IDAT")
          stream.insert(stream.end(), png.begin() + long(at) + 8,
                        png.begin() + long(at + 8 + length));
        at += 12 + length;
      }
      const std::size_t rowBytes = std::size_t(width * channels * bits / 8) + 1;
      std::vector<std::uint8_t> inflated(rowBytes * std::size_t(height));
      uLongf inflatedSize = uLongf(inflated.size());
      ASSERT_EQ(uncompress(inflated.data(), &inflatedSize, stream.data(), uLong(stream.size())),
                Z_OK);
      for (int y = 0; y < height; ++y)
        ++filtersSeen.at(inflated[std::size_t(y) * rowBytes]);
    }
  }
  for (int filter = 0; filter < 5; ++filter)
    EXPECT_GT(filtersSeen[std::size_t(filter)], 0) << "no row used filter " << filter;
}

// A 3x2 grey image with rows filtered by hand: Sub, then Paeth. The first row's "above" bytes
// are zero (PNG section 9.2), which a decoder that reads before the buffer would get wrong.
TEST(PngReader, UndoesHandWrittenFiltersToKnownValues) {
  const std::vector<std::uint8_t> filtered = {1, 10, 5, 5,     // Sub: 10, 15, 20
                                              4, 3,  4, 250};  // Paeth over (10, 15, 20)
  // Row 2, Paeth (pa = |b - c|, pb = |a - c|, pc = |a + b - 2c|; ties prefer a, then b):
  // x0: a=0, b=10, c=0: pa=10, pb=0, pc=10 -> b -> 3 + 10 = 13;
  // x1: a=13, b=15, c=10: pa=5, pb=3, pc=8 -> b -> 4 + 15 = 19;
  // x2: a=19, b=20, c=15: pa=5, pb=4, pc=9 -> b -> (250 + 20) mod 256 = 14.
  const std::string path = scratchFolder() + "/hand_filters.png";
  writeBytes(path, handMadePng(3, 2, 0, filtered));
  Image image(3, 2, 1);
  const Result<PngFastDecode> decoded = decodePngPixels(path, image);
  ASSERT_TRUE(decoded.ok()) << decoded.error();
  ASSERT_EQ(decoded.value(), PngFastDecode::Decoded);
  const std::array<int, 6> expected = {10, 15, 20, 13, 19, 14};
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(image.data()[i], float(expected[i]) * (1.0f / 255.0f)) << "value " << i;
  int channels = 0;
  const std::vector<float> libpng = decodedByLibpng(path, channels);
  ASSERT_EQ(libpng.size(), 6u);
  for (std::size_t i = 0; i < libpng.size(); ++i)
    EXPECT_EQ(image.data()[i], libpng[i]) << "value " << i;
}

// Colour-key transparency of grey and RGB images is OpenImageIO's: the fast path declines it and
// loadImage still reads it right (a grey image with tRNS gains an alpha channel). Palettes are
// the fast path's, expanded to the palette's colours.
TEST(PngReader, LeavesColourKeysToOpenImageIOAndExpandsPalettes) {
  const std::vector<std::uint8_t> filtered = {0, 7, 9};
  const std::string keyed = scratchFolder() + "/keyed.png";
  writeBytes(keyed, handMadePng(2, 1, 0, filtered, {{"tRNS", {0, 9}}}));
  Image grey(2, 1, 1);
  const Result<PngFastDecode> declined = decodePngPixels(keyed, grey);
  ASSERT_TRUE(declined.ok()) << declined.error();
  EXPECT_EQ(declined.value(), PngFastDecode::NotHandled);
  const Result<Image> loaded = loadImage(keyed);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  ASSERT_EQ(loaded->channels(), 2);
  EXPECT_EQ(loaded->at(0, 0, 1), 1.0f);  // 7 is opaque
  EXPECT_EQ(loaded->at(1, 0, 1), 0.0f);  // 9 is the transparent key

  const std::string indexed = scratchFolder() + "/indexed.png";
  writeBytes(indexed, handMadePng(2, 1, 3, {0, 0, 1}, {{"PLTE", {255, 0, 0, 0, 0, 255}}}));
  Image rgb(2, 1, 3);
  const Result<PngFastDecode> palette = decodePngPixels(indexed, rgb);
  ASSERT_TRUE(palette.ok()) << palette.error();
  EXPECT_EQ(palette.value(), PngFastDecode::Decoded);
  EXPECT_EQ(rgb.at(0, 0, 0), 1.0f);  // index 0: red
  EXPECT_EQ(rgb.at(0, 0, 2), 0.0f);
  EXPECT_EQ(rgb.at(1, 0, 0), 0.0f);  // index 1: blue
  EXPECT_EQ(rgb.at(1, 0, 2), 1.0f);
  const Result<Image> colours = loadImage(indexed);
  ASSERT_TRUE(colours.ok()) << colours.error();
  EXPECT_EQ(colours->at(1, 0, 2), 1.0f);
}

// Damage is reported with the file's name and what is wrong, never decoded into garbage.
TEST(PngReader, DamagedPixelDataIsRefusedWithTheReason) {
  const std::vector<std::uint8_t> good = {0, 1, 2, 3, 0, 4, 5, 6};
  struct Case {
    const char* name;
    std::vector<std::uint8_t> png;
    const char* reason;
  };
  std::vector<Case> cases;
  cases.push_back({"filter7.png", handMadePng(3, 2, 0, {7, 1, 2, 3, 0, 4, 5, 6}),
                   "row 0 has the unknown filter type 7"});
  cases.push_back(
      {"short.png", handMadePng(3, 2, 0, {0, 1, 2, 3, 0, 4}), "the zlib stream ends early"});
  cases.push_back({"long.png", handMadePng(3, 2, 0, {0, 1, 2, 3, 0, 4, 5, 6, 0, 7, 8, 9}),
                   "the zlib stream holds more than the image"});
  std::vector<std::uint8_t> badCrc = handMadePng(3, 2, 0, good);
  badCrc[badCrc.size() - 12 - 1] ^= 0x55;  // the IDAT chunk's CRC, just before IEND
  cases.push_back({"crc.png", badCrc, "the CRC of chunk \"IDAT\""});
  for (const Case& c : cases) {
    const std::string path = scratchFolder() + "/" + c.name;
    writeBytes(path, c.png);
    Image image(3, 2, 1);
    const Result<PngFastDecode> decoded = decodePngPixels(path, image);
    ASSERT_FALSE(decoded.ok()) << c.name;
    EXPECT_NE(decoded.error().find(path + ": the pixel data is damaged"), std::string::npos)
        << decoded.error();
    EXPECT_NE(decoded.error().find(c.reason), std::string::npos) << decoded.error();
    EXPECT_FALSE(loadImage(path).ok()) << c.name;
  }
}

// Rows are converted to floats on several threads, in waves whose floats cannot overwrite raw
// rows still to be read (convertRows): a map large enough for several waves and a serial tail
// decodes as libpng decodes it, and the first bad palette index in row order is the one named,
// whichever thread met it first.
TEST(PngReader, ConvertsLargeMapsInParallelWavesLikeLibpng) {
  for (int channels : {1, 3}) {
    const int width = 256, height = 300;
    const std::string path = scratchFolder() + "/waves_" + std::to_string(channels) + ".png";
    const std::vector<std::uint16_t> values = mixedContent(width, height, channels);
    {
      auto output = OIIO::ImageOutput::create(path);
      ASSERT_TRUE(output);
      ASSERT_TRUE(
          output->open(path, OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::UINT8)));
      ASSERT_TRUE(output->write_image(OIIO::TypeDesc::UINT16, values.data()));
      ASSERT_TRUE(output->close());
    }
    int libpngChannels = 0;
    const std::vector<float> expected = decodedByLibpng(path, libpngChannels);
    Image image(width, height, channels);
    const Result<PngFastDecode> decoded = decodePngPixels(path, image);
    ASSERT_TRUE(decoded.ok()) << decoded.error();
    ASSERT_EQ(decoded.value(), PngFastDecode::Decoded);
    ASSERT_EQ(image.valueCount(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
      ASSERT_EQ(image.data()[i], expected[i]) << path << " value " << i;
  }

  // A 200x300 palette image (four entries): its floats take 12 bytes a pixel against one raw
  // byte, so the first wave converts rows 0-273 and rows 274-299 go one by one.
  const int width = 200, height = 300;
  const auto paletteImage = [&](const std::vector<std::array<int, 2>>& bad) {
    std::vector<std::uint8_t> filtered;
    for (int y = 0; y < height; ++y) {
      filtered.push_back(0);
      for (int x = 0; x < width; ++x) {
        const bool isBad = std::find(bad.begin(), bad.end(), std::array<int, 2>{x, y}) != bad.end();
        filtered.push_back(std::uint8_t(isBad ? 9 : (x + y) % 4));
      }
    }
    return handMadePng(width, height, 3, filtered,
                       {{"PLTE", {0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255}}});
  };
  struct Case {
    const char* name;
    std::vector<std::array<int, 2>> bad;
    const char* reason;
  };
  const Case cases[] = {
      {"bad_in_wave.png", {{40, 200}, {3, 100}, {150, 260}}, "pixel (3, 100) uses palette index 9"},
      {"bad_in_tail.png", {{5, 290}, {7, 295}}, "pixel (5, 290) uses palette index 9"},
  };
  for (const Case& c : cases) {
    const std::string path = scratchFolder() + "/" + c.name;
    writeBytes(path, paletteImage(c.bad));
    Image image(width, height, 3);
    const Result<PngFastDecode> decoded = decodePngPixels(path, image);
    ASSERT_FALSE(decoded.ok()) << c.name;
    EXPECT_NE(decoded.error().find(std::string(c.reason) + "; the palette has 4 entries"),
              std::string::npos)
        << decoded.error();
  }
  const std::string good = scratchFolder() + "/palette_waves.png";
  writeBytes(good, paletteImage({}));
  Image image(width, height, 3);
  const Result<PngFastDecode> decoded = decodePngPixels(good, image);
  ASSERT_TRUE(decoded.ok()) << decoded.error();
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int index = (x + y) % 4;
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(image.at(x, y, c), index == c + 1 ? 1.0f : 0.0f) << x << ", " << y;
    }
  }
}

}  // namespace
}  // namespace relief::core
