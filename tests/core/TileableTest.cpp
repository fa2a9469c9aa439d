// Making maps tileable (core/generators/Tileable.h) on real photographs of surfaces: the made
// tile's wrap seam is no stronger than its interior (the bar: gradient energy across the
// seam within 1.2x of the interior's at the same spacing), a tile comes back unchanged, every map
// of a set gets the identical cut, the cross-fade keeps the histogram's mean and variance (Heitz
// and Neyret 2018's claim for their blending operator), and bad sets are refused with a message.
#include "core/generators/NormalFromHeight.h"
#include "core/generators/Tileable.h"
#include "core/image/ImageIO.h"
#include "support/TestPaths.h"
#include "support/TestPhotos.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace relief::core {
namespace {

constexpr double kSeamBar = 1.2;

Image inverted(const Image& image) {
  Image out = image;
  for (std::size_t i = 0; i < out.valueCount(); ++i)
    out.data()[i] = 1.0f - out.data()[i];
  return out;
}

struct Moments {
  double mean = 0.0, deviation = 0.0;
};

Moments momentsOf(const Image& image, int channel) {
  double sum = 0.0, squares = 0.0;
  for (std::size_t p = 0; p < image.pixelCount(); ++p) {
    const double value = image.data()[p * std::size_t(image.channels()) + std::size_t(channel)];
    sum += value;
    squares += value * value;
  }
  const double count = double(image.pixelCount());
  return {sum / count, std::sqrt(squares / count - (sum / count) * (sum / count))};
}

Result<TileableResult> tile(const Image& image, TileMethod method) {
  const TileMap maps[] = {{&image, TileMapRole::Data}};
  TileableOptions options;
  options.method = method;
  return makeTileable(maps, options);
}

TEST(Tileable, SurfacePhotographsHaveSeamsToRemove) {
  // The premise of the tests below: these photos do not tile as they are.
  for (const Image& photo : test::surfacePhotographs()) {
    EXPECT_GT(wrapSeamRatio(photo, false), 1.5);
    EXPECT_GT(wrapSeamRatio(photo, true), 1.5);
  }
}

TEST(Tileable, QuiltedSeamIsNoStrongerThanTheInterior) {
  const std::vector<Image> photos = test::surfacePhotographs();
  for (std::size_t i = 0; i < photos.size(); ++i) {
    const Image& photo = photos[i];
    Result<TileableResult> result = tile(photo, TileMethod::Quilt);
    ASSERT_TRUE(result) << result.error();
    const Image& made = result->maps.front();
    EXPECT_EQ(made.width(), photo.width());
    EXPECT_EQ(made.height(), photo.height());
    EXPECT_LE(wrapSeamRatio(made, false), kSeamBar) << i;
    EXPECT_LE(wrapSeamRatio(made, true), kSeamBar) << i;
    // The cuts inside the tile: the texels either side of a cut differ, summed along it, by no
    // more than 1.5x the pairs of texels around it (measured 0.56-1.09: a minimum-error path
    // through the overlap, smooth levels blended across it).
    EXPECT_LT(result->horizontal.cutRatio, 1.5) << i;
    EXPECT_LT(result->vertical.cutRatio, 1.5) << i;
  }
}

TEST(Tileable, CrossFadeKeepsTheHistogramAndTilesAStochasticTexture) {
  const std::vector<Image> photos = test::surfacePhotographs();
  for (std::size_t i = 0; i < photos.size(); ++i) {
    const Image& photo = photos[i];
    Result<TileableResult> result = tile(photo, TileMethod::CrossFade);
    ASSERT_TRUE(result) << result.error();
    const Image& made = result->maps.front();
    // Variance-preserving blending in Gaussianised space keeps mean and contrast (Heitz and
    // Neyret 2018's claim); a plain 50/50 cross-fade of two uncorrelated copies would divide
    // the deviation by up to sqrt(2) where they meet.
    const Moments before = momentsOf(photo, 0), after = momentsOf(made, 0);
    EXPECT_NEAR(after.mean, before.mean, 0.01) << i;
    EXPECT_NEAR(after.deviation / before.deviation, 1.0, 0.05) << i;
  }
  // The seam bar on the textures the method is for: grass and gravel, without long straight
  // structure. (Not the brick wall: blending two copies of courses ghosts them, and its border
  // measured 1.3-1.4; quilting, the default, is the method for it.)
  for (std::size_t i = 1; i < photos.size(); ++i) {
    Result<TileableResult> result = tile(photos[i], TileMethod::CrossFade);
    ASSERT_TRUE(result) << result.error();
    EXPECT_LE(wrapSeamRatio(result->maps.front(), false), kSeamBar) << i;
    EXPECT_LE(wrapSeamRatio(result->maps.front(), true), kSeamBar) << i;
  }
}

TEST(Tileable, TheBundledSamplesAlreadyTile) {
  // Made tileable when they were made: no axis is recut, so nothing changes (the same
  // judgement that lets a tile come back unchanged).
  for (const char* name : {"bricks", "cobblestones", "tiles"}) {
    for (const char* map : {"color", "height", "normal"}) {
      const std::string path =
          test::sourcePath("samples/") + name + "/" + name + "_" + map + ".png";
      Result<Image> image = loadImage(path);
      ASSERT_TRUE(image) << image.error();
      EXPECT_LE(wrapSeamRatio(image.value(), false), kSeamBar) << path;
      EXPECT_LE(wrapSeamRatio(image.value(), true), kSeamBar) << path;
    }
  }
}

TEST(Tileable, ATileComesBackUnchanged) {
  const Image photo = test::surfacePhotographs().at(2);
  Result<TileableResult> first = tile(photo, TileMethod::Quilt);
  ASSERT_TRUE(first) << first.error();
  for (const TileMethod method : {TileMethod::Quilt, TileMethod::CrossFade}) {
    Result<TileableResult> again = tile(first->maps.front(), method);
    ASSERT_TRUE(again) << again.error();
    EXPECT_TRUE(again->horizontal.alreadyTiled);
    EXPECT_TRUE(again->vertical.alreadyTiled);
    EXPECT_EQ(again->maps.front(), first->maps.front());
  }
}

TEST(Tileable, EveryMapOfASetGetsTheSameCut) {
  const Image photo = test::surfacePhotographs().at(0);
  const Image negative = inverted(photo);
  NormalFromHeightOptions normalOptions;
  normalOptions.strength = 4.0f;
  const Image normal = normalMapFromHeight(photo, normalOptions);
  for (const TileMethod method : {TileMethod::Quilt, TileMethod::CrossFade}) {
    const TileMap maps[] = {{&photo, TileMapRole::Data},
                            {&negative, TileMapRole::Data},
                            {&normal, TileMapRole::Normal}};
    TileableOptions options;
    options.method = method;
    Result<TileableResult> result = makeTileable(maps, options);
    ASSERT_TRUE(result) << result.error();
    const Image& made = result->maps[0];
    const Image& madeNegative = result->maps[1];
    // The negative's tile is the tile's negative: the same cut, the same weights. Quilting
    // copies texels (exact); the cross-fade goes through each map's own 4096-bin histogram.
    const double tolerance = method == TileMethod::Quilt ? 1e-6 : 2.0 / 4096.0;
    double worst = 0.0;
    for (std::size_t i = 0; i < made.valueCount(); ++i)
      worst = std::max(worst, std::abs(double(made.data()[i]) + madeNegative.data()[i] - 1.0));
    EXPECT_LE(worst, tolerance);
    // Blended normals are unit vectors again.
    const Image& madeNormal = result->maps[2];
    double worstLength = 0.0;
    for (std::size_t p = 0; p < madeNormal.pixelCount(); ++p) {
      const float* n = madeNormal.data() + p * 3;
      const double x = n[0] * 2.0 - 1.0, y = n[1] * 2.0 - 1.0, z = n[2] * 2.0 - 1.0;
      worstLength = std::max(worstLength, std::abs(std::sqrt(x * x + y * y + z * z) - 1.0));
    }
    EXPECT_LT(worstLength, 1e-4);
  }
}

TEST(Tileable, BadSetsAreRefusedWithAMessage) {
  const Image photo = test::surfacePhotographs().at(1);
  const Image smaller(256, 256, 1);
  const Image grey(photo.width(), photo.height(), 1);
  const auto error = [](std::initializer_list<TileMap> list, TileableOptions options = {}) {
    const std::vector<TileMap> maps(list);
    Result<TileableResult> result = makeTileable(maps, options);
    return result ? std::string() : result.error();
  };
  EXPECT_NE(error({{&photo}, {&smaller}}).find("differ in size"), std::string::npos);
  EXPECT_NE(error({{&photo}, {&grey, TileMapRole::Normal}}).find("three channels"),
            std::string::npos);
  TileableOptions tooWide;
  tooWide.patch = 600;
  EXPECT_NE(error({{&photo}}, tooWide).find("does not fit"), std::string::npos);
  EXPECT_NE(error({}).find("no maps"), std::string::npos);
  const Image tiny(8, 8, 1);
  EXPECT_NE(error({{&tiny}}).find("too small"), std::string::npos);
}

TEST(Tileable, SeamRatioOfAPeriodicPatternIsOne) {
  // The measure itself: a sine with a whole number of periods across the image tiles, and with
  // its phase turning once down the rows every column pair has the same energy summed over the
  // rows, so the wrap's equals the interior's mean; a ramp's wrap seam is a jump.
  Image sine(64, 32, 1), ramp(64, 32, 1);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 64; ++x) {
      const double phase = 2.0 * 3.14159265358979 * (3.0 * x / 64.0 + y / 32.0);
      sine.at(x, y, 0) = float(0.5 + 0.4 * std::sin(phase));
      ramp.at(x, y, 0) = float(x) / 63.0f;
    }
  }
  EXPECT_NEAR(wrapSeamRatio(sine, false), 1.0, 1e-3);
  EXPECT_NEAR(wrapSeamRatio(ramp, false), 63.0 * 63.0, 1.0);
}

}  // namespace
}  // namespace relief::core
