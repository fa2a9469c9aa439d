// The normals' spread folded into roughness mips (core/compression/RoughnessFold.h): the rule
// against values worked out by hand from its formula (kappa = (3r - r^3) / (1 - r^2), alpha'^2 =
// alpha^2 + 2 / kappa, alpha = roughness^2), its Toksvig limit near r = 1, and on synthetic bump
// fields whose averaged normals are known: stripes of normals tilted +-30 degrees (every level's
// average is (0, 0, cos 30)), a flat field (nothing folded), and random bumps (the mean length
// equals a direct average over each texel's footprint).
#include "core/compression/Compressor.h"
#include "core/compression/RoughnessFold.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace relief::core {
namespace {

constexpr double kPi = 3.14159265358979323846;

Image constant(int width, int height, float value) {
  Image image(width, height, 1);
  for (std::size_t i = 0; i < image.valueCount(); ++i)
    image.data()[i] = value;
  return image;
}

// Normals tilted by +-`degrees` about Y in alternating columns, as stored (0.5 + 0.5 n).
Image stripes(int width, int height, double degrees) {
  Image image(width, height, 3);
  const double s = std::sin(degrees * kPi / 180.0), c = std::cos(degrees * kPi / 180.0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double n[3] = {x % 2 ? s : -s, 0.0, c};
      for (int k = 0; k < 3; ++k)
        image.at(x, y, k) = float(0.5 + 0.5 * n[k]);
    }
  }
  return image;
}

TEST(RoughnessFold, TheRuleGivesTheHandWorkedValues) {
  // r = 0.9: kappa = (2.7 - 0.729) / 0.19 = 10.37368; roughness 0.3: alpha^2 = 0.0081,
  // alpha'^2 = 0.0081 + 2 / 10.37368 = 0.20090, roughness' = 0.20090^(1/4) = 0.66949.
  EXPECT_NEAR(foldedRoughness(0.3, 0.9), 0.669488, 1e-5);
  // r = cos 30 = 0.866025: kappa = 7.79423; roughness 0.2: 0.71284.
  EXPECT_NEAR(foldedRoughness(0.2, std::cos(kPi / 6.0)), 0.712835, 1e-5);
  EXPECT_DOUBLE_EQ(foldedRoughness(0.4, 1.0), 0.4) << "aligned normals add nothing";
  EXPECT_DOUBLE_EQ(foldedRoughness(0.4, 0.0), 1.0) << "cancelling normals: as rough as it goes";
  // Near r = 1 the rule is Toksvig's: 1 / kappa = 1 - r, so alpha'^2 = alpha^2 + 2 (1 - r).
  const double r = 0.999, alpha = 0.05 * 0.05;
  const double toksvig = std::pow(alpha * alpha + 2.0 * (1.0 - r), 0.25);
  EXPECT_NEAR(foldedRoughness(0.05, r), toksvig, 1e-3 * toksvig);
  // More spread, more roughness.
  EXPECT_LT(foldedRoughness(0.3, 0.95), foldedRoughness(0.3, 0.9));
}

TEST(RoughnessFold, TiltedStripesWidenEveryLevelByTheirSpread) {
  const Image normals = stripes(16, 8, 30.0);
  const std::vector<Image> lengths = meanNormalLengths(normals);
  ASSERT_EQ(int(lengths.size()), mipLevelCount(16, 8) - 1);
  const std::vector<Image> levels =
      foldedRoughnessLevels(constant(16, 8, 0.2f), normals, MipFilter::Box);
  ASSERT_EQ(levels.size(), lengths.size());
  const double expected = foldedRoughness(0.2, std::cos(kPi / 6.0));
  for (std::size_t k = 0; k < levels.size(); ++k) {
    EXPECT_EQ(levels[k].width(), std::max(1, 16 >> (k + 1)));
    for (int y = 0; y < levels[k].height(); ++y) {
      for (int x = 0; x < levels[k].width(); ++x) {
        EXPECT_NEAR(lengths[k].at(x, y, 0), std::cos(kPi / 6.0), 1e-5) << "level " << k + 1;
        EXPECT_NEAR(levels[k].at(x, y, 0), expected, 1e-5) << "level " << k + 1;
      }
    }
  }
}

TEST(RoughnessFold, AFlatFieldFoldsNothing) {
  Image flat(8, 8, 3);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      flat.at(x, y, 0) = flat.at(x, y, 1) = 0.5f;
      flat.at(x, y, 2) = 1.0f;
    }
  }
  Image roughness(8, 8, 1);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x)
      roughness.at(x, y, 0) = float(x + y) / 16.0f;
  }
  const std::vector<Image> folded = foldedRoughnessLevels(roughness, flat, MipFilter::Kaiser);
  const std::vector<Image> plain = buildMipChain(roughness, MapSlot::Roughness, MipFilter::Kaiser);
  ASSERT_EQ(folded.size() + 1, plain.size());
  for (std::size_t k = 0; k < folded.size(); ++k) {
    for (int y = 0; y < folded[k].height(); ++y) {
      for (int x = 0; x < folded[k].width(); ++x)
        EXPECT_NEAR(folded[k].at(x, y, 0), plain[k + 1].at(x, y, 0), 1e-6);
    }
  }
}

TEST(RoughnessFold, MeanLengthsAverageEachTexelsWholeFootprint) {
  std::mt19937 random(3);
  std::normal_distribution<double> slope(0.0, 0.4);
  Image normals(16, 16, 3);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      const double n[3] = {slope(random), slope(random), 1.0};
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + 1.0);
      for (int k = 0; k < 3; ++k)
        normals.at(x, y, k) = float(0.5 + 0.5 * n[k] / length);
    }
  }
  const std::vector<Image> lengths = meanNormalLengths(normals);
  // Level 2 (4x4 texels of 4x4 each), directly: the unit vectors summed over the footprint.
  for (int ty = 0; ty < 4; ++ty) {
    for (int tx = 0; tx < 4; ++tx) {
      double sum[3] = {0.0, 0.0, 0.0};
      for (int y = 4 * ty; y < 4 * ty + 4; ++y) {
        for (int x = 4 * tx; x < 4 * tx + 4; ++x) {
          double n[3], length = 0.0;
          for (int k = 0; k < 3; ++k) {
            n[k] = normals.at(x, y, k) * 2.0 - 1.0;
            length += n[k] * n[k];
          }
          for (int k = 0; k < 3; ++k)
            sum[k] += n[k] / std::sqrt(length) / 16.0;
        }
      }
      EXPECT_NEAR(lengths[1].at(tx, ty, 0),
                  std::sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]), 1e-5);
    }
  }
  for (std::size_t k = 1; k < lengths.size(); ++k) {
    double previous = 0.0, current = 0.0;
    for (std::size_t i = 0; i < lengths[k - 1].valueCount(); ++i)
      previous += lengths[k - 1].data()[i] / double(lengths[k - 1].valueCount());
    for (std::size_t i = 0; i < lengths[k].valueCount(); ++i)
      current += lengths[k].data()[i] / double(lengths[k].valueCount());
    EXPECT_LE(current, previous + 1e-6) << "wider footprints spread at least as much";
  }
}

TEST(RoughnessFold, CompressionFoldsWithTheNormalMapOrSaysWhy) {
  const Image roughness = constant(16, 8, 0.2f);
  const Image normals = stripes(16, 8, 30.0);
  CompressionSettings settings{TextureFormat::Bc4, CompressionQuality::Normal, true};
  settings.roughnessFromNormals = true;
  Result<CompressedTexture> missing = compressMap(roughness, MapSlot::Roughness, settings);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().find("needs the normal map"), std::string::npos) << missing.error();
  const Image small = stripes(8, 8, 30.0);
  Result<CompressedTexture> mismatch =
      compressMap(roughness, MapSlot::Roughness, settings, {}, &small);
  ASSERT_FALSE(mismatch.ok());
  EXPECT_NE(mismatch.error().find("16x8"), std::string::npos) << mismatch.error();
  Result<CompressedTexture> folded =
      compressMap(roughness, MapSlot::Roughness, settings, {}, &normals);
  ASSERT_TRUE(folded.ok()) << folded.error();
  // Level 1 decodes to the folded value (BC4 holds a constant block within a 255th).
  const Image level = decodeAsMap(folded.value(), 1).value();
  EXPECT_NEAR(level.at(0, 0, 0), foldedRoughness(0.2, std::cos(kPi / 6.0)), 1.0 / 255.0);
  EXPECT_NEAR(decodeAsMap(folded.value(), 0).value().at(0, 0, 0), 0.2, 1.0 / 255.0)
      << "level 0 as is";
}

}  // namespace
}  // namespace relief::core
