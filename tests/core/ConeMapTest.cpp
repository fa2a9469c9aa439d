// The cone map (core/tracing/ConeMap.h) against brute force: for every cell, points p spread
// over the cell and points q spread over three repeats of the map in each direction, the
// repeating bilinear field never rises above the cone, f(q) - f(p) <= |q - p| / w (the
// guarantee of Bán, Valasek et al., EGSR 2024, which texel-sampled cones lack). Checked on random
// noise, one-texel walls and spikes, on odd and non-square maps, for depth maps. And the cones
// are not uselessly narrow: on a smooth field they reach a stated fraction of the widest
// cone the field allows, 1 / (largest gradient).
#include "core/tracing/ConeMap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace relief::core {
namespace {

Image fieldImage(int width, int height, const std::function<float(int, int)>& value) {
  Image image(width, height, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x)
      image.at(x, y, 0) = value(x, y);
  }
  return image;
}

ConeMap conesOf(const Image& image, bool depth = false) {
  return buildConeMap(image, 0, depth);
}

// The repeating bilinear field in cell coordinates (texel (i, j) at (i, j), rows as stored).
double bilinear(const Image& image, bool depth, double x, double y) {
  const int w = image.width(), h = image.height();
  const double fx = std::floor(x), fy = std::floor(y);
  const double a = x - fx, b = y - fy;
  const auto texel = [&](double tx, double ty) {
    const int ix = ((int(tx) % w) + w) % w, iy = ((int(ty) % h) + h) % h;
    const double v = image.at(ix, iy, 0);
    return depth ? 1.0 - v : v;
  };
  return (1 - a) * (1 - b) * texel(fx, fy) + a * (1 - b) * texel(fx + 1, fy) +
         (1 - a) * b * texel(fx, fy + 1) + a * b * texel(fx + 1, fy + 1);
}

// The largest f(q) - f(p) - |q - p| / w over the sampled points (positive: the cone holds
// part of the surface). p: n x n points per cell, edges included; q: `perTexel` per texel (the
// texels, where the field has its peaks, among them) over
// [-w/2, 3w/2) (the nearest repeat of any point to a p in the map lies there).
// Every `cellStep`-th cell along each axis is checked.
double worstViolation(const Image& image, bool depth = false, int n = 4, int perTexel = 3,
                      int cellStep = 1) {
  const ConeMap cones = conesOf(image, depth);
  const int w = image.width(), h = image.height();
  EXPECT_EQ(cones.width, w);
  EXPECT_EQ(cones.height, h);
  double worst = -1e9;
  for (int cy = 0; cy < h; cy += cellStep) {
    for (int cx = 0; cx < w; cx += cellStep) {
      const double ratio = cones.at(cx, cy);
      EXPECT_GT(ratio, 0.0) << cx << "," << cy;
      for (int py = 0; py < n; ++py) {
        for (int px = 0; px < n; ++px) {
          const double x = cx + px / double(n - 1), y = cy + py / double(n - 1);
          const double fp = bilinear(image, depth, x, y);
          for (int qy = -perTexel * h / 2; qy < perTexel * h * 3 / 2; ++qy) {
            for (int qx = -perTexel * w / 2; qx < perTexel * w * 3 / 2; ++qx) {
              const double u = double(qx) / perTexel, v = double(qy) / perTexel;
              const double rise = bilinear(image, depth, u, v) - fp;
              if (rise <= 0.0)
                continue;
              worst = std::max(worst, rise - std::hypot(u - x, v - y) / ratio);
            }
          }
        }
      }
    }
  }
  return worst;
}

TEST(ConeMap, NoConeHoldsTheBilinearSurfaceOfNoise) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const Image noise = fieldImage(9, 7, [&](int, int) { return unit(random); });
  EXPECT_LE(worstViolation(noise), 1e-6);
  EXPECT_LE(worstViolation(noise, true), 1e-6);
}

TEST(ConeMap, NoConeHoldsOneTexelWallsOrSpikes) {
  // Walls one texel wide on a low floor: the cones beside them must close before the wall,
  // between sample points too (a texel-sampled cone sees the wall only at its centres).
  const Image walls =
      fieldImage(12, 10, [](int x, int y) { return x == 4 || y == 7 ? 1.0f : 0.1f; });
  EXPECT_LE(worstViolation(walls), 1e-6);
  const Image spikes = fieldImage(
      11, 11, [](int x, int y) { return (x == 2 && y == 3) || (x == 8 && y == 9) ? 1.0f : 0.0f; });
  EXPECT_LE(worstViolation(spikes), 1e-6);
}

TEST(ConeMap, NoConeHoldsASmoothFieldOnANonSquareMap) {
  const Image smooth = fieldImage(16, 6, [](int x, int y) {
    return float(0.5 + 0.25 * std::sin(2 * std::numbers::pi * x / 16.0) +
                 0.2 * std::cos(2 * std::numbers::pi * y / 6.0));
  });
  EXPECT_LE(worstViolation(smooth), 1e-6);
}

// A 64x64 map (sizes the generator's 4x4 blocks divide, so its wide shells are bounded over
// blocks) of a low, slightly noisy floor with one spike 0.9 above it: the cones of cells 16 to 32
// cells from it are set by the shells past 15 cells, bounded over blocks (one block less of
// reach there breaks this test). Every third cell is checked, for time.
TEST(ConeMap, NoConeHoldsTheSurfaceWhereWideShellsAreBoundedOverBlocks) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> noise(0.0f, 0.01f);
  const Image floor = fieldImage(
      64, 64, [&](int x, int y) { return x == 3 && y == 5 ? 1.0f : 0.1f + noise(random); });
  const ConeMap cones = conesOf(floor);
  EXPECT_GT(*std::max_element(cones.ratios.begin(), cones.ratios.end()), 20.0f);
  EXPECT_LE(worstViolation(floor, false, 2, 1, 3), 1e-6);
}

TEST(ConeMap, AFlatMapHasTheWidestCones) {
  const Image flat = fieldImage(8, 8, [](int, int) { return 0.5f; });
  const ConeMap cones = conesOf(flat);
  for (float ratio : cones.ratios)
    EXPECT_EQ(ratio, kMaxConeRatio);
}

// A cosine ridge h = 0.5 + 0.5 cos(2 pi x / 64): its steepest gradient is G = pi / 64 per
// texel, so no cone anywhere can be wider than about 1 / G (from the foot of the steepest
// slope). The bounds used here lose to that: the 3x3 Lipschitz ring takes the steepest
// gradient within a texel, and the rings beyond measure from the cell's lowest corner to a
// block's highest. Half of 1 / G everywhere, and near the crest (where the field is flat and
// only far slopes limit the cone) wider than 1 / G, is what they must still give.
TEST(ConeMap, ConesOnASmoothFieldAreNotNeedlesslyNarrow) {
  constexpr int kSize = 64;
  const double steepest = std::numbers::pi / kSize;
  const Image ridge = fieldImage(kSize, 4, [](int x, int) {
    return float(0.5 + 0.5 * std::cos(2 * std::numbers::pi * x / kSize));
  });
  const ConeMap cones = conesOf(ridge);
  float narrowest = kMaxConeRatio;
  for (float ratio : cones.ratios)
    narrowest = std::min(narrowest, ratio);
  EXPECT_GE(narrowest, 0.5 / steepest);
  EXPECT_GT(cones.at(0, 0), 1.0 / steepest);
}

}  // namespace
}  // namespace relief::core
