// Environment maps (core/shading/EnvironmentMaps.h): the equirectangular layout the shaders
// share, the built-ins against the formulas they are made from, and files: EXR and Radiance
// HDR load; 8-bit, non-2:1, enormous and damaged files are refused with the file's name.
#include "core/image/ImageIO.h"
#include "core/shading/EnvironmentMaps.h"
#include "core/view/Environment.h"
#include "support/TestPaths.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace relief::test {
namespace {

using core::Image;

// The mean of a channel over one row of an equirect (one polar angle).
float rowMean(const Image& image, int y, int channel = 0) {
  double sum = 0.0;
  for (int x = 0; x < image.width(); ++x)
    sum += image.at(x, y, channel);
  return float(sum / image.width());
}

Image filled(int width, int height, float value) {
  Image image(width, height, 3);
  for (std::size_t i = 0; i < image.valueCount(); ++i)
    image.data()[i] = value;
  return image;
}

TEST(EnvironmentMaps, TheLayoutPutsTheZenithOnTopAndMinusZInTheMiddle) {
  const auto near = [](glm::vec2 a, glm::vec2 b) { return glm::length(a - b) < 1e-5f; };
  EXPECT_TRUE(near(core::equirectUv({0, 0, -1}), {0.5f, 0.5f}));
  EXPECT_TRUE(near(core::equirectUv({1, 0, 0}), {0.75f, 0.5f}));
  EXPECT_TRUE(near(core::equirectUv({-1, 0, 0}), {0.25f, 0.5f}));
  EXPECT_NEAR(core::equirectUv({0, 1, 0}).y, 0.0f, 1e-6f);
  EXPECT_NEAR(core::equirectUv({0, -1, 0}).y, 1.0f, 1e-6f);
  EXPECT_NEAR(core::equirectUv({0, 0, 1}).x, 1.0f, 1e-6f);  // the seam, behind the camera
  for (glm::vec3 d : {glm::vec3(0.3f, 0.5f, -0.8f), glm::vec3(-0.7f, -0.2f, 0.4f)}) {
    const glm::vec3 back = core::equirectDirection(core::equirectUv(d));
    EXPECT_LT(glm::length(back - glm::normalize(d)), 1e-5f);
  }
}

// The rotation turns what the unrotated map shows toward -Z to +X at 90 degrees: looking
// along +X then reads the map's -Z.
TEST(EnvironmentMaps, RotationTurnsTheMapTowardPlusX) {
  core::Environment environment;
  environment.rotationDeg = 90.0f;
  const glm::vec3 looked = environment.worldToEnvironment() * glm::vec3(1, 0, 0);
  EXPECT_LT(glm::length(looked - glm::vec3(0, 0, -1)), 1e-6f);
  const glm::vec3 up = environment.worldToEnvironment() * glm::vec3(0, 1, 0);
  EXPECT_LT(glm::length(up - glm::vec3(0, 1, 0)), 1e-6f);
}

TEST(EnvironmentMaps, TheUniformIsOneEverywhere) {
  const Image uniform = core::makeBuiltInEnvironment(core::BuiltInEnvironment::Uniform, 8);
  ASSERT_EQ(uniform.width(), 16);  // at the height asked for
  for (int y = 0; y < uniform.height(); ++y)
    for (int x = 0; x < uniform.width(); ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(uniform.at(x, y, c), 1.0f);
}

// The CIE standard overcast sky: L(theta) = Lz (1 + 2 cos theta) / 3 (a third of the zenith at
// the horizon); the ground is a diffuse albedo 0.2 under it, 0.2 * 7 / 9 of Lz.
TEST(EnvironmentMaps, TheSkyFollowsTheCieOvercastSky) {
  const int height = 256;
  const Image sky = core::makeBuiltInEnvironment(core::BuiltInEnvironment::Sky, height);
  const auto cie = [&](int row) {
    return 1.0 + 2.0 * std::cos((double(row) + 0.5) / height * M_PI);  // row centres
  };
  const float zenith = rowMean(sky, 0, 1);
  for (int row : {height / 3, height / 2 - 3}) {  // 60.3 and 88.2 degrees from the zenith
    EXPECT_NEAR(rowMean(sky, row, 1) / zenith, cie(row) / cie(0), 1e-3) << row;
  }
  const float ground = rowMean(sky, height - 10, 0);
  EXPECT_NEAR(ground, 0.2 * 7.0 / 9.0, 1e-4);
  // Greys stay near grey: the tint is a cool sky, not a colour.
  EXPECT_GT(sky.at(0, 0, 2), sky.at(0, 0, 0));
}

// The studio: dark walls, a floor darker still, and soft boxes far brighter than either.
TEST(EnvironmentMaps, TheStudioHasSoftBoxesOnDarkWalls) {
  const Image studio = core::makeBuiltInEnvironment(core::BuiltInEnvironment::Studio, 256);
  float brightest = 0.0f;
  for (std::size_t i = 0; i < studio.valueCount(); i += 4)
    brightest = std::max(brightest, studio.data()[i]);
  EXPECT_GE(brightest, 5.0f);
  // The key box, toward azimuth 105 (from -Z toward +X), 35 degrees up.
  const float azimuth = glm::radians(105.0f), elevation = glm::radians(35.0f);
  const glm::vec3 key(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                      -std::cos(elevation) * std::cos(azimuth));
  const glm::vec2 uv = core::equirectUv(key);
  EXPECT_NEAR(studio.at(int(uv.x * 512), int(uv.y * 256), 0), 6.0f + 0.1f + 0.1f * key.y, 0.01f);
  EXPECT_LT(rowMean(studio, 250), 0.1f);        // the floor
  EXPECT_LT(studio.at(256, 128 - 5, 0), 0.2f);  // the wall behind the material
}

class EnvironmentFiles : public ::testing::Test {
 protected:
  std::string path(const std::string& name) { return scratchFolder() + "/" + name; }
};

TEST_F(EnvironmentFiles, AnExrLoadsAsRadianceWithValuesAboveOne) {
  Image image = filled(64, 32, 0.25f);
  image.at(10, 5, 0) = 5000.0f;
  image.at(11, 5, 1) = -3.0f;  // negative radiance is not light
  const std::string file = path("bright.exr");
  ASSERT_TRUE(core::saveImage(image, file, core::SampleFormat::Float).ok());
  core::Result<Image> loaded = core::loadEnvironmentFile(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->width(), 64);
  EXPECT_EQ(loaded->channels(), 4);
  EXPECT_EQ(loaded->at(10, 5, 0), 5000.0f);
  EXPECT_EQ(loaded->at(11, 5, 1), 0.0f);
  EXPECT_EQ(loaded->at(20, 20, 2), 0.25f);
  // Cached while the file is unchanged: the same image, not a second load.
  auto first = core::environmentRadiance(file);
  auto second = core::environmentRadiance(file);
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(first.value().get(), second.value().get());
}

TEST_F(EnvironmentFiles, ARadianceHdrLoads) {
  const std::string file = path("sky.hdr");
  Image image = filled(32, 16, 2.5f);
  auto output = OIIO::ImageOutput::create(file);
  ASSERT_TRUE(output);
  ASSERT_TRUE(output->open(file, OIIO::ImageSpec(32, 16, 3, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, image.data()));
  output->close();
  core::Result<Image> loaded = core::loadEnvironmentFile(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_NEAR(loaded->at(3, 3, 1), 2.5f, 0.05f);  // RGBE keeps 8 bits of mantissa
}

TEST_F(EnvironmentFiles, FilesThatHoldNoUsableEnvironmentAreRefusedByName) {
  const std::string png = path("photo.png");
  ASSERT_TRUE(core::saveImage(filled(64, 32, 0.5f), png, core::SampleFormat::UInt8).ok());
  const std::string square = path("square.exr");
  ASSERT_TRUE(core::saveImage(filled(32, 32, 0.5f), square, core::SampleFormat::Half).ok());
  const std::string cut = path("cut.exr");
  ASSERT_TRUE(core::saveImage(filled(256, 128, 0.5f), cut, core::SampleFormat::Float).ok());
  std::filesystem::resize_file(cut, std::filesystem::file_size(cut) / 2);
  const std::string missing = path("missing.exr");
  struct Case {
    std::string file;
    std::string reason;
  };
  for (const Case& c :
       {Case{png, "holds no radiance above 1"}, Case{square, "twice as wide as it is tall"},
        Case{cut, ""}, Case{missing, ""}}) {
    core::Result<Image> loaded = core::loadEnvironmentFile(c.file);
    ASSERT_FALSE(loaded.ok()) << c.file;
    EXPECT_NE(loaded.error().find(c.file), std::string::npos) << loaded.error();
    EXPECT_NE(loaded.error().find(c.reason), std::string::npos) << loaded.error();
    EXPECT_FALSE(core::environmentRadiance(c.file).ok());
  }
}

// An EXR whose header claims 32768 x 16384 texels: refused from the header, before any pixel
// memory. Made by rewriting a small file's data window (a box2i: xMin, yMin, xMax, yMax).
TEST_F(EnvironmentFiles, AnEnormousEnvironmentIsRefusedFromItsHeader) {
  const std::string file = path("enormous.exr");
  ASSERT_TRUE(core::saveImage(filled(64, 32, 1.0f), file, core::SampleFormat::Half).ok());
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string attribute = std::string("dataWindow") + '\0' + "box2i" + '\0';
  const std::size_t at = bytes.find(attribute);
  ASSERT_NE(at, std::string::npos);
  const std::size_t box = at + attribute.size() + 4;  // after the attribute's size
  const std::int32_t corners[4] = {0, 0, 32767, 16383};
  std::memcpy(&bytes[box], corners, sizeof corners);
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << bytes;
  }
  core::Result<Image> loaded = core::loadEnvironmentFile(file);
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().find(file), std::string::npos) << loaded.error();
  EXPECT_NE(loaded.error().find("32768"), std::string::npos) << loaded.error();
}

}  // namespace
}  // namespace relief::test
