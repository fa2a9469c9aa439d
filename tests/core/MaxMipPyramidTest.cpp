// The maximum-mipmap pyramid (core/tracing/MaxMipPyramid.h) against brute force: every cell of
// every level is the maximum of the bilinear field over its footprint, which for bilinear
// interpolation is the largest texel among the footprint's cell corners (wrapping), on square,
// odd and non-square maps, for heights and depth maps.
#include "core/tracing/MaxMipPyramid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace relief::core {
namespace {

Image randomHeights(int width, int height, unsigned seed) {
  Image image(width, height, 2);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      image.at(x, y, 0) = unit(random);
      image.at(x, y, 1) = unit(random);
    }
  }
  return image;
}

// Level-0 cells [first, end) covered by cell c of a level of `cells` cells, at `level`: 2^level
// each, the last to the map's edge.
std::pair<int, int> footprint(int c, int cells, int level, int mapSize) {
  const int first = c << level;
  const int end = c == cells - 1 ? mapSize : (c + 1) << level;
  return {first, end};
}

void expectBruteForce(const Image& image, int channel, bool depth) {
  const MaxMipPyramid pyramid = buildMaxMipPyramid(image, channel, depth);
  const int w = image.width(), h = image.height();
  const auto texel = [&](int x, int y) {
    const float v = image.at(x % w, y % h, channel);
    return depth ? 1.0f - v : v;
  };
  ASSERT_FALSE(pyramid.levels.empty());
  EXPECT_EQ(pyramid.levels.back().width, 1);
  EXPECT_EQ(pyramid.levels.back().height, 1);
  for (std::size_t k = 0; k < pyramid.levels.size(); ++k) {
    const MaxMipLevel& level = pyramid.levels[k];
    // OpenGL's mip sizes: floor halving, at least 1.
    EXPECT_EQ(level.width, std::max(w >> k, 1));
    EXPECT_EQ(level.height, std::max(h >> k, 1));
    for (int cy = 0; cy < level.height; ++cy) {
      for (int cx = 0; cx < level.width; ++cx) {
        const auto [x0, x1] = footprint(cx, level.width, int(k), w);
        const auto [y0, y1] = footprint(cy, level.height, int(k), h);
        float most = 0.0f;
        for (int y = y0; y < y1; ++y) {
          for (int x = x0; x < x1; ++x) {
            most = std::max(
                {most, texel(x, y), texel(x + 1, y), texel(x, y + 1), texel(x + 1, y + 1)});
          }
        }
        ASSERT_EQ(level.at(cx, cy), most) << "level " << k << " cell " << cx << ", " << cy;
      }
    }
  }
}

TEST(MaxMipPyramid, EveryCellIsTheMaximumOfItsFootprint) {
  expectBruteForce(randomHeights(16, 16, 1), 0, false);
  expectBruteForce(randomHeights(13, 7, 2), 0, false);  // odd: dangling children
  expectBruteForce(randomHeights(1, 9, 3), 1, false);   // a column
  expectBruteForce(randomHeights(20, 33, 4), 1, true);  // depth map: bounds of 1 - depth
}

TEST(MaxMipPyramid, BoundsTheBilinearFieldBetweenTexels) {
  // The bound holds between texel centres too, where the shader intersects the patch.
  const Image image = randomHeights(8, 8, 5);
  const MaxMipPyramid pyramid = buildMaxMipPyramid(image, 0, false);
  for (int i = 0; i < 4000; ++i) {
    const double u = (i % 61) / 61.0 * 8.0 - 0.5, v = (i / 61) / 66.0 * 8.0 - 0.5;
    const int cx = int(std::floor(u)), cy = int(std::floor(v));
    const double a = u - cx, b = v - cy;
    const auto t = [&](int x, int y) { return double(image.at((x + 8) % 8, (y + 8) % 8, 0)); };
    const double bilinear = t(cx, cy) * (1 - a) * (1 - b) + t(cx + 1, cy) * a * (1 - b) +
                            t(cx, cy + 1) * (1 - a) * b + t(cx + 1, cy + 1) * a * b;
    EXPECT_LE(bilinear, pyramid.levels[0].at((cx + 8) % 8, (cy + 8) % 8) + 1e-6);
    EXPECT_LE(bilinear, pyramid.levels.back().at(0, 0) + 1e-6);
  }
}

}  // namespace
}  // namespace relief::core
