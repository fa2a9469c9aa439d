// Maps that check each other (core/generators/MapCheck.h). The normal maps are built in closed
// form from a height field of sines (not with Relief's generator), in each convention and sign,
// and stored at 8 bits as files hold them; the expectations come from that construction. The
// bundled samples, whose normal maps were made from their height maps, must raise no finding.
#include "core/generators/MapCheck.h"
#include "core/image/ImageIO.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relief::core {
namespace {

constexpr int kSize = 128;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A tileable field of a few sines with features along both axes; `seed` shifts the phases and
// picks other frequencies, so two seeds are unrelated surfaces. Heights in 0..1.
struct SineField {
  int seed;
  double value(double x, double y) const {
    double h = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Wave w = wave(k);
      h += w.amplitude * std::sin(kTwoPi * (w.fx * x + w.fy * y) / kSize + w.phase);
    }
    return 0.5 + 0.5 * h;
  }
  // d value / dx and d value / dy with y up the image (y rows run down, so -d/drow).
  void slope(double x, double y, double& dx, double& dyUp) const {
    dx = dyUp = 0.0;
    for (int k = 0; k < 3; ++k) {
      const Wave w = wave(k);
      const double c = 0.5 * w.amplitude *
                       std::cos(kTwoPi * (w.fx * x + w.fy * y) / kSize + w.phase) * kTwoPi / kSize;
      dx += c * w.fx;
      dyUp -= c * w.fy;
    }
  }

 private:
  struct Wave {
    double fx, fy, phase, amplitude;
  };
  Wave wave(int k) const {
    static const Wave kWaves[2][3] = {{{2, 1, 0.3, 0.4}, {-1, 3, 1.1, 0.35}, {4, 2, 2.0, 0.2}},
                                      {{3, -2, 0.9, 0.4}, {1, 4, 0.2, 0.35}, {5, 1, 1.7, 0.2}}};
    return kWaves[seed % 2][k];
  }
};

double to8Bits(double value) {
  return std::round(std::clamp(value, 0.0, 1.0) * 255.0) / 255.0;
}

Image heightMap(const SineField& field, bool depth) {
  Image image(kSize, kSize, 1);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const double h = field.value(x, y);
      image.at(x, y, 0) = float(to8Bits(depth ? 1.0 - h : h));
    }
  }
  return image;
}

// normalize(-s dh/dx, -s dh/dy, 1), Y negated for DirectX, as n * 0.5 + 0.5 at 8 bits.
Image normalMap(const SineField& field, double strength, NormalConvention convention) {
  Image image(kSize, kSize, 3);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      double dx = 0.0, dy = 0.0;
      field.slope(x, y, dx, dy);
      double n[3] = {-strength * dx, -strength * dy, 1.0};
      if (convention == NormalConvention::DirectX)
        n[1] = -n[1];
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = float(to8Bits(n[c] / length * 0.5 + 0.5));
    }
  }
  return image;
}

constexpr double kStrength = 20.0;  // slopes up to about 0.7: a bumpy, not a flat, surface

TEST(MapCheck, AMatchingOpenGlPairAgreesAndGivesItsStrength) {
  const SineField field{0};
  const Image height = heightMap(field, false);
  const Image normal = normalMap(field, kStrength, NormalConvention::OpenGl);
  Result<MapCheckResult> result = checkMaps(normal, &height);
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_GT(*result->correlationX, 0.9);
  EXPECT_GT(*result->correlationY, 0.9);
  EXPECT_TRUE(result->pairMatches);
  EXPECT_EQ(result->convention, NormalConvention::OpenGl);
  EXPECT_EQ(result->heightIsDepth, false);
  // The slopes were made with kStrength per unit of height per texel; Sobel's smoothing and
  // the 8-bit heights bend the fit by a few percent at these frequencies.
  EXPECT_NEAR(*result->strength, kStrength, 0.08 * kStrength);
  EXPECT_TRUE(
      mapCheckFindings(result.value(), NormalConvention::OpenGl, false, "n.png", "h.png").empty());
}

TEST(MapCheck, FindsADirectXNormalMapWithAndWithoutTheHeightMap) {
  const SineField field{0};
  const Image height = heightMap(field, false);
  const Image normal = normalMap(field, kStrength, NormalConvention::DirectX);
  Result<MapCheckResult> paired = checkMaps(normal, &height);
  ASSERT_TRUE(paired.ok());
  EXPECT_GT(*paired->correlationX, 0.9);
  EXPECT_LT(*paired->correlationY, -0.9);
  EXPECT_EQ(paired->convention, NormalConvention::DirectX);
  EXPECT_EQ(paired->heightIsDepth, false);
  const std::vector<std::string> findings =
      mapCheckFindings(paired.value(), NormalConvention::OpenGl, false, "n.png", "h.png");
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_NE(findings[0].find("n.png is a DirectX"), std::string::npos) << findings[0];
  // Declared DirectX, it agrees.
  EXPECT_TRUE(mapCheckFindings(paired.value(), NormalConvention::DirectX, false, "n", "h").empty());

  // The normal map alone: a height field's slopes have no curl; flipped Y gives them some.
  Result<MapCheckResult> alone = checkMaps(normal, nullptr);
  ASSERT_TRUE(alone.ok());
  EXPECT_EQ(alone->convention, NormalConvention::DirectX);
  EXPECT_LT(alone->curlFlipped, 0.1 * alone->curlAsStored);
  EXPECT_FALSE(alone->heightIsDepth.has_value());
  Result<MapCheckResult> openGl =
      checkMaps(normalMap(field, kStrength, NormalConvention::OpenGl), nullptr);
  EXPECT_EQ(openGl->convention, NormalConvention::OpenGl);
}

TEST(MapCheck, FindsAHeightMapThatStoresDepth) {
  const SineField field{0};
  const Image depth = heightMap(field, true);
  for (NormalConvention convention : {NormalConvention::OpenGl, NormalConvention::DirectX}) {
    const Image normal = normalMap(field, kStrength, convention);
    Result<MapCheckResult> result = checkMaps(normal, &depth);
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(result->heightIsDepth, true);
    EXPECT_EQ(result->convention, convention);
    const std::vector<std::string> findings =
        mapCheckFindings(result.value(), convention, false, "n.png", "h.png");
    ASSERT_EQ(findings.size(), 1u);
    EXPECT_NE(findings[0].find("h.png is inverted"), std::string::npos) << findings[0];
    EXPECT_TRUE(mapCheckFindings(result.value(), convention, true, "n", "h").empty());
  }
}

// Game data pairs normal maps with height maps of twice their resolution: the height map is
// resized to the normal map's, and the strength is then per normal-map texel.
TEST(MapCheck, ComparesAHeightMapOfAnotherResolution) {
  const SineField field{0};
  Image large(2 * kSize, 2 * kSize, 1);
  for (int y = 0; y < large.height(); ++y) {
    for (int x = 0; x < large.width(); ++x)
      large.at(x, y, 0) = float(to8Bits(field.value(0.5 * x - 0.25, 0.5 * y - 0.25)));
  }
  const Image normal = normalMap(field, kStrength, NormalConvention::DirectX);
  Result<MapCheckResult> result = checkMaps(normal, &large);
  ASSERT_TRUE(result.ok()) << result.error();
  EXPECT_EQ(result->convention, NormalConvention::DirectX);
  EXPECT_EQ(result->heightIsDepth, false);
  EXPECT_NEAR(*result->strength, kStrength, 0.1 * kStrength);
}

TEST(MapCheck, FindsMapsOfDifferentSurfaces) {
  const Image height = heightMap(SineField{1}, false);
  const Image normal = normalMap(SineField{0}, kStrength, NormalConvention::OpenGl);
  Result<MapCheckResult> result = checkMaps(normal, &height);
  ASSERT_TRUE(result.ok());
  EXPECT_LT(std::abs(*result->correlationX), kMapCheckThreshold);
  EXPECT_LT(std::abs(*result->correlationY), kMapCheckThreshold);
  EXPECT_FALSE(result->pairMatches);
  EXPECT_FALSE(result->heightIsDepth.has_value());
  // The normal map on its own is still a valid OpenGL map.
  EXPECT_EQ(result->convention, NormalConvention::OpenGl);
  const std::vector<std::string> findings =
      mapCheckFindings(result.value(), NormalConvention::OpenGl, false, "n.png", "h.png");
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_NE(findings[0].find("do not describe the same surface"), std::string::npos);
}

TEST(MapCheck, TheBundledSamplesRaiseNoFinding) {
  for (const char* name : {"bricks", "cobblestones", "tiles"}) {
    const std::string folder = test::sourcePath("samples/") + name + "/" + name;
    Result<Image> normal = loadImage(folder + "_normal.png");
    Result<Image> height = loadImage(folder + "_height.png");
    ASSERT_TRUE(normal.ok() && height.ok()) << name;
    Result<MapCheckResult> result = checkMaps(normal.value(), &height.value());
    ASSERT_TRUE(result.ok()) << result.error();
    EXPECT_TRUE(result->pairMatches) << name;
    EXPECT_EQ(result->convention, NormalConvention::OpenGl) << name;
    EXPECT_EQ(result->heightIsDepth, false) << name;
    EXPECT_TRUE(
        mapCheckFindings(result.value(), NormalConvention::OpenGl, false, "normal", "height")
            .empty())
        << name;
  }
}

TEST(MapCheck, RefusesMapsItCannotCompare) {
  const Image normal = normalMap(SineField{0}, kStrength, NormalConvention::OpenGl);
  const Image strip(kSize, kSize / 2, 1);
  Result<MapCheckResult> shapes = checkMaps(normal, &strip);
  ASSERT_FALSE(shapes.ok());
  EXPECT_NE(shapes.error().find("different shapes"), std::string::npos) << shapes.error();
  Result<MapCheckResult> grey = checkMaps(heightMap(SineField{0}, false), nullptr);
  ASSERT_FALSE(grey.ok());
  EXPECT_NE(grey.error().find("1 channel"), std::string::npos) << grey.error();
}

}  // namespace
}  // namespace relief::core
