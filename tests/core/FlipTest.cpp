// FLIP (core/compression/Flip.h) against the paper's equations worked out independently here:
// on flat images the contrast filters change nothing and there are no features, so the error
// is the colour pipeline alone (CIELab, Hunt, HyAB, the redistribution), computed below in
// double precision from the CIE definitions; at a black/white step the feature pipeline's edge
// response is the step itself (the edge kernel's positive weights sum to 1, its negative ones
// to -1). Identical images give 0; a moved edge raises the error where the edge was.
#include "core/compression/Flip.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

namespace relief::core {
namespace {

using Colour = std::array<double, 3>;

Image flat(const Colour& srgb, int size = 24) {
  Image image(size, size, 3, ColorSpace::Srgb);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = float(srgb[std::size_t(c)]);
  return image;
}

// The colour pipeline by hand: sRGB -> linear -> XYZ (IEC 61966-2-1) -> L*a*b* (D65) -> Hunt
// (a, b times L/100) -> HyAB -> ^0.7 -> redistributed with pc = 0.4, pt = 0.95 against the
// green-blue maximum.
Colour huntLab(const Colour& srgb) {
  Colour linear{};
  for (int c = 0; c < 3; ++c) {
    const double v = srgb[std::size_t(c)];
    linear[std::size_t(c)] = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  }
  const double X = 0.4124 * linear[0] + 0.3576 * linear[1] + 0.1805 * linear[2];
  const double Y = 0.2126 * linear[0] + 0.7152 * linear[1] + 0.0722 * linear[2];
  const double Z = 0.0193 * linear[0] + 0.1192 * linear[1] + 0.9505 * linear[2];
  const auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
  };
  const double fx = f(X / 0.95047), fy = f(Y), fz = f(Z / 1.08883);
  const double L = 116.0 * fy - 16.0;
  return {L, L / 100.0 * 500.0 * (fx - fy), L / 100.0 * 200.0 * (fy - fz)};
}

double byHand(const Colour& a, const Colour& b) {
  const auto hyab = [](const Colour& p, const Colour& q) {
    return std::abs(p[0] - q[0]) + std::hypot(p[1] - q[1], p[2] - q[2]);
  };
  const double cmax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), 0.7);
  const double e = std::pow(hyab(huntLab(a), huntLab(b)), 0.7);
  return e < 0.4 * cmax ? 0.95 / (0.4 * cmax) * e : 0.95 + (e - 0.4 * cmax) / (0.6 * cmax) * 0.05;
}

TEST(Flip, IdenticalImagesScoreZero) {
  Image image(40, 30, 3, ColorSpace::Srgb);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  for (std::size_t i = 0; i < image.valueCount(); ++i)
    image.data()[i] = value(random);
  const FlipResult result = measureFlip(image, image);
  EXPECT_EQ(result.mean, 0.0);
  EXPECT_EQ(result.maxError, 0.0);
}

TEST(Flip, FlatColoursScoreTheColourPipelineByHand) {
  const Colour pairs[][2] = {{{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}},
                             {{0.8, 0.2, 0.1}, {0.8, 0.4, 0.1}},
                             {{0.1, 0.3, 0.7}, {0.2, 0.3, 0.5}},
                             {{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}}};  // the maximum: 1
  for (const auto& pair : pairs) {
    const FlipResult result =
        measureFlip(flat(pair[0]), flat(pair[1]), kFlipDefaultPixelsPerDegree, true);
    const double expected = byHand(pair[0], pair[1]);
    // Every pixel, the edges' included (clamped borders keep a flat image flat).
    EXPECT_NEAR(result.mean, expected, 2e-3) << pair[1][0] << " " << pair[1][1];
    EXPECT_NEAR(result.maxError, expected, 2e-3);
    // Float rounding in the derivative filters leaves responses near 1e-8 on a flat image,
    // which the square root (qf = 0.5) lifts to 1e-4: nothing next to the colour error.
    EXPECT_NEAR(result.featureError.at(5, 5, 0), 0.0, 1e-3);
  }
}

TEST(Flip, AStepIsAnEdgeAsStrongAsTheStep) {
  // Black left of x = 12, white from it on; the test image flat black. At the two pixels by the
  // step the edge response is the luminance step, 1, and the point response smaller (the point
  // kernel's centre weight over two: 0.15), so the feature error is (1 / sqrt 2)^0.5.
  Image step(24, 24, 3, ColorSpace::Srgb), black(24, 24, 3, ColorSpace::Srgb);
  for (int y = 0; y < 24; ++y)
    for (int x = 12; x < 24; ++x)
      for (int c = 0; c < 3; ++c)
        step.at(x, y, c) = 1.0f;
  const FlipResult result = measureFlip(step, black, kFlipDefaultPixelsPerDegree, true);
  const double expected = std::pow(1.0 / std::sqrt(2.0), 0.5);
  EXPECT_NEAR(result.featureError.at(11, 12, 0), expected, 1e-3);
  EXPECT_NEAR(result.featureError.at(12, 12, 0), expected, 1e-3);
  // Far from the step the white half differs from black by the colour pipeline alone.
  EXPECT_NEAR(result.featureError.at(23, 12, 0), 0.0, 1e-3);
}

TEST(Flip, AMovedEdgeRaisesTheErrorWhereTheEdgeWas) {
  // A 0.3 | 0.7 edge moved one pixel left: the feature pipeline engages along the edge (the
  // edge strength moved), nowhere far from it, and raises the score there above the colour
  // error alone (c^(1 - f) > c for 0 < c < 1, f > 0).
  constexpr int kSize = 64;
  Image reference(kSize, kSize, 3, ColorSpace::Srgb);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x)
      for (int c = 0; c < 3; ++c)
        reference.at(x, y, c) = x < kSize / 2 ? 0.3f : 0.7f;
  Image moved = reference;
  for (int y = 0; y < kSize; ++y)
    for (int c = 0; c < 3; ++c)
      moved.at(kSize / 2 - 1, y, c) = 0.7f;
  const FlipResult result = measureFlip(reference, moved, kFlipDefaultPixelsPerDegree, true);
  const int edge = kSize / 2 - 2;  // beside the moved column, where the edge strength changed
  EXPECT_GT(result.featureError.at(edge, 20, 0), 0.2f);
  EXPECT_GT(result.errorMap.at(edge, 20, 0), 1.2f * result.colourError.at(edge, 20, 0));
  EXPECT_LT(result.featureError.at(4, 20, 0), 1e-3f);
  EXPECT_LT(result.errorMap.at(4, 20, 0), 1e-3f);
  // The worst pixel is by the edge.
  float worst = 0.0f;
  int worstX = 0;
  for (int x = 0; x < kSize; ++x) {
    if (result.errorMap.at(x, 20, 0) > worst) {
      worst = result.errorMap.at(x, 20, 0);
      worstX = x;
    }
  }
  EXPECT_NEAR(worstX, kSize / 2 - 1, 2);
}

}  // namespace
}  // namespace relief::core
