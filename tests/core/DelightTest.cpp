// Removing baked light (core/generators/Delight.h): a known albedo, lit by a smooth light that
// swings +-40% across the map, comes back within a stated error once the light is divided out;
// the light's range is reported; strength 0 and a flat photo change nothing.
#include "core/generators/Delight.h"
#include "core/generators/Generators.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relief::core {
namespace {

constexpr int kDelightTestSize = 128;

// Linear albedo: a checker of 4-texel squares (0.25 and 0.6) tinted per channel, fine detail
// well under the radius, the way a surface's own pattern is.
float albedo(int x, int y, int c) {
  const bool light = ((x / 4) + (y / 4)) % 2 == 0;
  return (light ? 0.6f : 0.25f) * (1.0f - 0.15f * float(c));
}

// A tileable light: 1 + 0.4 sin(x) cos(y) over the map, the sun through a window.
float lightAt(int x, int y) {
  const double t = 2.0 * std::numbers::pi / kDelightTestSize;
  return float(1.0 + 0.4 * std::sin(t * x) * std::cos(t * y));
}

Image photo(bool lit) {
  Image image(kDelightTestSize, kDelightTestSize, 3, ColorSpace::Srgb);
  for (int y = 0; y < kDelightTestSize; ++y) {
    for (int x = 0; x < kDelightTestSize; ++x) {
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = linearToSrgb(albedo(x, y, c) * (lit ? lightAt(x, y) : 1.0f));
    }
  }
  return image;
}

// RMS of (recovered / true - 1) over the texels and channels, after scaling the recovered map
// to the true one's mean (delighting keeps the mean light, not the absolute exposure).
double relativeError(const Image& recovered) {
  double sumRecovered = 0.0, sumTrue = 0.0;
  for (int y = 0; y < kDelightTestSize; ++y) {
    for (int x = 0; x < kDelightTestSize; ++x) {
      for (int c = 0; c < 3; ++c) {
        sumRecovered += srgbToLinear(recovered.at(x, y, c));
        sumTrue += albedo(x, y, c);
      }
    }
  }
  const double scale = sumTrue / sumRecovered;
  double squares = 0.0;
  for (int y = 0; y < kDelightTestSize; ++y) {
    for (int x = 0; x < kDelightTestSize; ++x) {
      for (int c = 0; c < 3; ++c) {
        const double ratio = scale * srgbToLinear(recovered.at(x, y, c)) / albedo(x, y, c);
        squares += (ratio - 1.0) * (ratio - 1.0);
      }
    }
  }
  return std::sqrt(squares / (3.0 * kDelightTestSize * kDelightTestSize));
}

TEST(Delight, RecoversAnAlbedoUnderASmoothLight) {
  const Image lit = photo(true);
  EXPECT_GT(relativeError(lit), 0.18) << "the light must be there to remove (RMS 0.4 / 2)";
  DelightOptions options;
  // Six texels: the 8-texel checker averages out (a Gaussian of sigma 6 keeps e^-11 of it) while
  // the light, 128 texels a period, keeps e^-(6^2 |k|^2 / 2) = 0.917 of its swing; what the blur
  // misses stays in the albedo.
  options.radius = 6.0;
  const DelightResult result = delight(lit, options);
  EXPECT_LT(relativeError(result.albedo), 0.05);
  EXPECT_EQ(result.albedo.colorSpace(), ColorSpace::Srgb);
  // The estimated light swings 0.917 x 0.4 about its mean, with an RMS of half that.
  const double swing =
      0.4 * std::exp(-36.0 * 2.0 * std::pow(2.0 * std::numbers::pi / kDelightTestSize, 2) / 2.0);
  EXPECT_NEAR(result.lightLow, 1.0 - swing, 0.02);
  EXPECT_NEAR(result.lightHigh, 1.0 + swing, 0.02);
  EXPECT_NEAR(result.lightRms, swing / 2.0, 0.01);
}

TEST(Delight, StrengthZeroAndAnEvenlyLitPhotoChangeNothing) {
  DelightOptions none;
  none.strength = 0.0;
  const Image lit = photo(true);
  EXPECT_EQ(delight(lit, none).albedo, lit);
  DelightOptions options;
  options.radius = 6.0;
  const DelightResult flat = delight(photo(false), options);
  EXPECT_LT(relativeError(flat.albedo), 0.01);
  EXPECT_LT(flat.lightRms, 0.01);
}

TEST(Delight, RunsAsAGeneratorAndReportsTheLight) {
  const Image lit = photo(true);
  GeneratorRequest request;
  request.kind = GeneratorKind::Delight;
  request.inputs = {&lit};
  request.values = defaultGeneratorValues(GeneratorKind::Delight);
  request.values[std::size_t(findGeneratorOption(GeneratorKind::Delight, "radius"))] = 6.0;
  Result<GeneratedMap> generated = runGenerator(request);
  ASSERT_TRUE(generated.ok()) << generated.error();
  EXPECT_LT(relativeError(generated->image), 0.05);
  ASSERT_EQ(generated->notes.size(), 1u);
  EXPECT_NE(generated->notes[0].find("the baked light ranged from"), std::string::npos);
  EXPECT_EQ(generatorInfo(GeneratorKind::Delight).output, MapSlot::Color);
}

}  // namespace
}  // namespace relief::core
