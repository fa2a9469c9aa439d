// The mip chain's filters (core/compression/MipChain.h) against what is known of them
// analytically. A two-texel average (box) passes a sine of f cycles per texel with amplitude
// |cos(pi f)| (the average of two samples half a period of 2 pi f apart): a period-16 sine keeps
// cos(pi/16) = 0.981 of it, and a period-3 sine, above the next level's Nyquist limit, comes
// through aliased at cos(pi/3) = 0.5. The Kaiser-windowed sinc keeps more of the first (its
// passband is flatter) and removes most of the second (its stopband starts at the new Nyquist
// limit). A one-texel checkerboard averages to 0.5 under both (pairs of opposite texels at equal
// weights).
#include "core/compression/MipChain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relief::core {
namespace {

// A sine along x with `period` texels, 0.5 +- 0.4, `width` x 8, linear data.
Image sine(int width, double period) {
  Image image(width, 8, 1);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < width; ++x)
      image.at(x, y, 0) = float(0.5 + 0.4 * std::sin(2.0 * std::numbers::pi * x / period));
  return image;
}

// The amplitude of the level's sine of `period` texels (the level's, after aliasing), over the
// source's 0.4: the Fourier coefficient at that period along a row (a whole number of periods
// fits, so the bin is exact whatever the sampling phase).
double relativeAmplitude(const Image& level, double period) {
  double re = 0.0, im = 0.0;
  for (int x = 0; x < level.width(); ++x) {
    const double angle = 2.0 * std::numbers::pi * x / period;
    re += (level.at(x, 2, 0) - 0.5) * std::cos(angle);
    im += (level.at(x, 2, 0) - 0.5) * std::sin(angle);
  }
  return 2.0 * std::hypot(re, im) / level.width() / 0.4;
}

TEST(MipFilter, BoxPassesAndAliasesAsTwoTexelAveragesDo) {
  // Period 16 over 128 texels: level 1 holds period 8, sampled where the pairs' mean peaks
  // within cos(pi/8) of the true peak.
  // Period 16 becomes period 8 one level down; period 3 (2/3 of a cycle per new texel) folds
  // back to period 3 of the new texels.
  const double kept = relativeAmplitude(downsampleForSlot(sine(128, 16.0), MapSlot::Height), 8.0);
  EXPECT_NEAR(kept, std::cos(std::numbers::pi / 16.0), 1e-3);
  const double aliased =
      relativeAmplitude(downsampleForSlot(sine(96, 3.0), MapSlot::Height, MipFilter::Box), 3.0);
  EXPECT_NEAR(aliased, 0.5, 1e-3);
}

TEST(MipFilter, KaiserKeepsThePassbandAndStopsWhatWouldAlias) {
  const double kept = relativeAmplitude(
      downsampleForSlot(sine(128, 16.0), MapSlot::Height, MipFilter::Kaiser), 8.0);
  const double aliased =
      relativeAmplitude(downsampleForSlot(sine(96, 3.0), MapSlot::Height, MipFilter::Kaiser), 3.0);
  std::printf("kaiser: period 16 keeps %.4f, period 3 leaves %.4f\n", kept, aliased);
  EXPECT_GT(kept, std::cos(std::numbers::pi / 16.0));  // flatter than the box
  EXPECT_LT(aliased, 0.1);                             // a fifth of the box's 0.5 at most
}

TEST(MipFilter, ACheckerboardAveragesToHalfUnderBoth) {
  Image checker(64, 64, 1);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      checker.at(x, y, 0) = float((x + y) % 2);
  for (MipFilter filter : {MipFilter::Box, MipFilter::Kaiser}) {
    const Image level = downsampleForSlot(checker, MapSlot::Height, filter);
    for (int y = 0; y < level.height(); ++y)
      for (int x = 0; x < level.width(); ++x)
        EXPECT_NEAR(level.at(x, y, 0), 0.5f, 1e-5f) << mipFilterName(filter);
  }
}

TEST(MipFilter, KaiserKeepsNormalsUnitAndColourInRange) {
  Image normals(32, 32, 3), colour(32, 32, 3, ColorSpace::Srgb);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const double a = std::sin(x * 0.9) * 0.8, b = std::cos(y * 1.3) * 0.5;
      const double z = std::sqrt(std::max(0.0, 1.0 - a * a * 0.5 - b * b * 0.5));
      const double length = std::sqrt(a * a * 0.5 + b * b * 0.5 + z * z);
      normals.at(x, y, 0) = float(a * std::sqrt(0.5) / length * 0.5 + 0.5);
      normals.at(x, y, 1) = float(b * std::sqrt(0.5) / length * 0.5 + 0.5);
      normals.at(x, y, 2) = float(z / length * 0.5 + 0.5);
      for (int c = 0; c < 3; ++c)
        colour.at(x, y, c) = float((x / 2 + y / 2 + c) % 2);  // hard edges: the lobes overshoot
    }
  }
  for (const Image& level : buildMipChain(normals, MapSlot::Normal, MipFilter::Kaiser)) {
    for (int y = 0; y < level.height(); ++y) {
      for (int x = 0; x < level.width(); ++x) {
        double length = 0.0;
        for (int c = 0; c < 3; ++c)
          length += std::pow(level.at(x, y, c) * 2.0 - 1.0, 2.0);
        EXPECT_NEAR(std::sqrt(length), 1.0, 1e-4);
      }
    }
  }
  const std::vector<Image> chain = buildMipChain(colour, MapSlot::Color, MipFilter::Kaiser);
  EXPECT_EQ(chain.size(), 6u);
  for (const Image& level : chain)
    for (std::size_t i = 0; i < level.valueCount(); ++i)
      EXPECT_TRUE(level.data()[i] >= 0.0f && level.data()[i] <= 1.0f);
  EXPECT_EQ(findMipFilter("kaiser"), MipFilter::Kaiser);
  EXPECT_EQ(findMipFilter("lanczos"), std::nullopt);
}

// Alpha coverage (MipChain.h: scaleAlphaToCoverage): thin wavy strokes with a soft profile (a
// cut-out's alpha) lose coverage of the 0.5 cutoff level by level when averaged; scaled, every
// level of 256 texels or more keeps level 0's coverage within 1% of it plus one texel's share
// (the quantile's resolution; texels tied at the threshold go over together), and the colour
// channels are untouched.
TEST(MipFilter, AlphaCoverageIsKeptEveryLevel) {
  Image foliage(256, 256, 4);
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const double stroke = std::abs(std::sin(2.0 * std::numbers::pi * x / 37.0 +
                                              3.0 * std::sin(2.0 * std::numbers::pi * y / 53.0)));
      foliage.at(x, y, 0) = float(x) / 255.0f;
      foliage.at(x, y, 1) = 0.5f;
      foliage.at(x, y, 2) = float(y) / 255.0f;
      foliage.at(x, y, 3) = float(std::max(0.0, 1.0 - 4.0 * stroke));
    }
  }
  const float cutoff = 0.5f;
  const double coverage = alphaCoverage(foliage, cutoff);
  ASSERT_GT(coverage, 0.05);
  const std::vector<Image> plain = buildMipChain(foliage, MapSlot::Color, MipFilter::Box);
  std::vector<Image> kept = plain;
  for (std::size_t k = 1; k < kept.size(); ++k)
    scaleAlphaToCoverage(kept[k], cutoff, coverage);
  EXPECT_LT(alphaCoverage(plain[3], cutoff), 0.8 * coverage) << "averaging thins the strokes";
  for (std::size_t k = 1; k < kept.size() && kept[k].pixelCount() >= 256; ++k) {
    const double texel = 1.0 / double(kept[k].pixelCount());
    EXPECT_NEAR(alphaCoverage(kept[k], cutoff), coverage, 0.01 * coverage + texel) << "level " << k;
    for (int y = 0; y < kept[k].height(); ++y) {
      for (int x = 0; x < kept[k].width(); ++x) {
        EXPECT_EQ(kept[k].at(x, y, 0), plain[k].at(x, y, 0));
        EXPECT_LE(kept[k].at(x, y, 3), 1.0f);
      }
    }
  }
  // Nothing to keep: the level is brought just under the cutoff.
  Image faint = plain[1];
  scaleAlphaToCoverage(faint, cutoff, 0.0);
  EXPECT_EQ(alphaCoverage(faint, cutoff), 0.0);
}

}  // namespace
}  // namespace relief::core
