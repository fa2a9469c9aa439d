// Roughness and metallic guesses (core/generators/SurfaceGuess.h) against their stated rules:
// roughness runs linearly from `roughest` at the 5th percentile of luminance to `smoothest` at
// the 95th, saturation and cavities move it the stated way and amount; metallic is 1 inside the
// brightness and saturation ranges and 0 outside, so steel reads as metal, gold only once the
// saturation range takes it in, dark stone never. Through the generator table too (CLI, GUI).
#include "core/generators/Generators.h"
#include "core/generators/SurfaceGuess.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relief::core {
namespace {

constexpr int kSize = 100;

// Grey columns whose linear luminance rises from 0 to 0.99 across the image, stored linear.
Image greyRamp() {
  Image image(kSize, kSize, 3, ColorSpace::Linear);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = float(x) / 100.0f;
  return image;
}

TEST(RoughnessGuess, RunsFromRoughestToSmoothestBetweenThePercentiles) {
  RoughnessGuessOptions options;
  options.cavity = 0.0;
  const SurfaceGuess guess = guessRoughness(greyRamp(), nullptr, options);
  // Columns 0..99 hold luminance x/100; the 5th and 95th percentiles are about 0.05 and 0.95.
  EXPECT_NEAR(guess.map.at(2, 50, 0), options.roughest, 1e-6);    // below the 5th: clamped
  EXPECT_NEAR(guess.map.at(98, 50, 0), options.smoothest, 1e-6);  // above the 95th
  const double t = (0.5 - 0.05) / (0.95 - 0.05);
  EXPECT_NEAR(guess.map.at(50, 50, 0),
              options.roughest + (options.smoothest - options.roughest) * t, 0.01);
  for (int x = 1; x < kSize; ++x)
    EXPECT_LE(guess.map.at(x, 0, 0), guess.map.at(x - 1, 0, 0)) << "brighter is never rougher";
  EXPECT_NEAR(guess.low, options.smoothest, 1e-6);
  EXPECT_NEAR(guess.high, options.roughest, 1e-6);
}

TEST(RoughnessGuess, SaturationAndCavitiesMoveItTheStatedWay) {
  // Left half grey, right half pure red of the same linear luminance (0.2): only the saturation
  // term tells them apart.
  Image color(kSize, kSize, 3, ColorSpace::Linear);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float grey = 0.2f;
      color.at(x, y, 0) = x < kSize / 2 ? grey : grey / 0.2126f;
      color.at(x, y, 1) = x < kSize / 2 ? grey : 0.0f;
      color.at(x, y, 2) = x < kSize / 2 ? grey : 0.0f;
    }
  }
  RoughnessGuessOptions options;
  options.cavity = 0.0;
  options.saturation = 0.6;
  const SurfaceGuess glossy = guessRoughness(color, nullptr, options);
  // Equal luminance: the saturated red is 0.6 * 1.0 * 0.5 = 0.3 smoother.
  EXPECT_NEAR(glossy.map.at(10, 10, 0) - glossy.map.at(90, 10, 0), 0.3, 0.02);

  // A pit in a flat height map: rougher inside, unchanged far away; nothing without cavity.
  Image height(kSize, kSize, 1);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      height.at(x, y, 0) =
          1.0f - 0.5f * std::exp(-float((x - 50) * (x - 50) + (y - 50) * (y - 50)) / 20.0f);
  const Image flat = greyRamp();
  RoughnessGuessOptions cavities;
  cavities.cavity = 1.0;
  const SurfaceGuess pitted = guessRoughness(flat, &height, cavities);
  cavities.cavity = 0.0;
  const SurfaceGuess plain = guessRoughness(flat, &height, cavities);
  EXPECT_GT(pitted.map.at(50, 50, 0), plain.map.at(50, 50, 0) + 0.2);
  EXPECT_NEAR(pitted.map.at(10, 10, 0), plain.map.at(10, 10, 0), 1e-3);
}

TEST(MetallicGuess, SteelIsMetalGoldOnlyWhenAskedDarkStoneNever) {
  // Four patches, stored sRGB as photographs are: steel (light grey), gold, dark stone, white.
  const float patches[4][3] = {
      {0.80f, 0.80f, 0.82f}, {0.95f, 0.77f, 0.34f}, {0.25f, 0.24f, 0.22f}, {0.97f, 0.97f, 0.97f}};
  Image color(40, 10, 3, ColorSpace::Srgb);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 40; ++x)
      for (int c = 0; c < 3; ++c)
        color.at(x, y, c) = patches[x / 10][c];
  MetallicGuessOptions options;
  SurfaceGuess guess = guessMetallic(color, options);
  EXPECT_FLOAT_EQ(guess.map.at(5, 5, 0), 1.0f);   // steel
  EXPECT_FLOAT_EQ(guess.map.at(15, 5, 0), 0.0f);  // gold is too saturated for grey metals
  EXPECT_FLOAT_EQ(guess.map.at(25, 5, 0), 0.0f);  // dark stone
  EXPECT_FLOAT_EQ(guess.map.at(35, 5, 0), 1.0f);  // white: the range's top reaches 1
  EXPECT_NEAR(guess.metalFraction, 0.5, 1e-9);
  options.saturationHigh = 0.7;
  guess = guessMetallic(color, options);
  EXPECT_FLOAT_EQ(guess.map.at(15, 5, 0), 1.0f);  // gold taken in
  options.brightnessHigh = 0.8;
  guess = guessMetallic(color, options);
  EXPECT_FLOAT_EQ(guess.map.at(35, 5, 0), 0.0f);  // white plaster left out
}

TEST(SurfaceGuessGenerators, RunFromTheTableIntoTheirSlotsAndRefuseMismatchedMaps) {
  EXPECT_EQ(generatorInfo(GeneratorKind::Roughness).output, MapSlot::Roughness);
  EXPECT_EQ(generatorInfo(GeneratorKind::Metallic).output, MapSlot::Metallic);
  EXPECT_EQ(findGenerator("roughness"), GeneratorKind::Roughness);
  EXPECT_EQ(findGenerator("metallic"), GeneratorKind::Metallic);
  const Image color = greyRamp();
  Result<GeneratedMap> roughness = runGenerator({GeneratorKind::Roughness, {&color}, {}, 1.0});
  ASSERT_TRUE(roughness) << roughness.error();
  EXPECT_EQ(roughness->image.channels(), 1);
  ASSERT_FALSE(roughness->notes.empty());
  EXPECT_NE(roughness->notes.front().find("no cavities"), std::string::npos);
  Result<GeneratedMap> metallic = runGenerator({GeneratorKind::Metallic, {&color}, {}, 1.0});
  ASSERT_TRUE(metallic) << metallic.error();
  EXPECT_NE(metallic->notes.front().find("read as metal"), std::string::npos);
  const Image smaller(50, 50, 1);
  Result<GeneratedMap> mismatched =
      runGenerator({GeneratorKind::Roughness, {&color, &smaller}, {}, 1.0});
  ASSERT_FALSE(mismatched);
  EXPECT_NE(mismatched.error().find("50x50"), std::string::npos) << mismatched.error();
}

}  // namespace
}  // namespace relief::core
