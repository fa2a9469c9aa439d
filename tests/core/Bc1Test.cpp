// Relief's BC1 encoder (Bc1Encoder.cpp): against libsquish's cluster fit on real photographs,
// its three-colour mode where that mode wins, flat colours, the luminance weights, and that no
// block ever uses the three-colour mode's transparent-black index (Relief's BC1 is opaque, and a
// reader treating DXT1 as having 1-bit alpha would punch holes). What the GPU decodes from our
// blocks is CompressedSamplingTest's.
#include "core/compression/BlockCodecs.h"
#include "core/compression/CompressionMetrics.h"
#include "core/compression/Compressor.h"
#include "support/ImageCompare.h"
#include "support/TestPhotos.h"

#include <gtest/gtest.h>
#include <squish.h>

#include <cmath>

namespace relief::core {
namespace {

CompressedTexture ours(const Image& map, CompressionQuality quality, bool perceptual = false) {
  CompressionSettings settings{TextureFormat::Bc1, quality, false};
  settings.perceptual = perceptual;
  return compressMap(map, MapSlot::Color, settings).value();
}

// libsquish's BC1 of the same map, uniform weights (its default), decoded by our decoder.
CompressedTexture libsquish(const Image& map, int fit) {
  std::vector<squish::u8> rgba(map.pixelCount() * 4);
  for (std::size_t p = 0; p < map.pixelCount(); ++p) {
    for (int c = 0; c < 4; ++c) {
      const float v = c < 3 ? map.data()[p * std::size_t(map.channels()) + std::size_t(c)] : 1.0f;
      rgba[p * 4 + std::size_t(c)] = squish::u8(std::lround(v * 255.0f));
    }
  }
  CompressedTexture texture = ours(map, CompressionQuality::Fast);  // the same metadata
  squish::CompressImage(rgba.data(), map.width(), map.height(), texture.levels[0].data.data(),
                        squish::kDxt1 | fit, nullptr);
  return texture;
}

// The quality bar, as quality (the speed is tools/bench-compress's: 11x libsquish's
// cluster fit): the mean PSNR over the photographs at least cluster fit's less 0.05 dB at
// normal, above it at best, and fast above libsquish's range fit. Measured on these crops:
// fast 1.6 dB above range fit, normal within 0.03 dB of cluster fit, best 0.09 dB above it
// (its search is crunch's quality class: docs/compression.md); the bound is 0.06.
TEST(Bc1Test, MatchesLibsquishClusterFitOnPhotographs) {
  const std::vector<Image> photos = test::photographCrops(256);
  ASSERT_FALSE(photos.empty());
  double fast = 0, normal = 0, best = 0, rangeFit = 0, clusterFit = 0;
  for (const Image& photo : photos) {
    const double n = double(photos.size());
    fast += test::decodedPsnr(photo, ours(photo, CompressionQuality::Fast)) / n;
    normal += test::decodedPsnr(photo, ours(photo, CompressionQuality::Normal)) / n;
    best += test::decodedPsnr(photo, ours(photo, CompressionQuality::Best)) / n;
    rangeFit += test::decodedPsnr(photo, libsquish(photo, squish::kColourRangeFit)) / n;
    clusterFit += test::decodedPsnr(photo, libsquish(photo, squish::kColourClusterFit)) / n;
  }
  std::printf(
      "BC1 mean PSNR: ours fast %.3f normal %.3f best %.3f; libsquish range fit %.3f, "
      "cluster fit %.3f\n",
      fast, normal, best, rangeFit, clusterFit);
  EXPECT_GE(normal, clusterFit - 0.05);
  EXPECT_GE(best, clusterFit + 0.06);
  EXPECT_GE(fast, rangeFit + 1.0);
  EXPECT_GE(best, normal);
  EXPECT_GE(normal, fast);
}

// Against crunch 1.04's best (npm texture-compressor: -DXT1 -dxtQuality uber -uniformMetrics
// -mipMode None, no RDO), decoded by our decoder, on the same crops: the issue asks best to reach
// it. Measured when best's cluster search became exhaustive and evaluated its 48 best splits:
// 35.575 dB against crunch's 35.586 (0.011 short; it was 0.03 short before), each crop within
// 0.04. The floor keeps best within 0.02 dB of crunch on the mean, so a regression fails.
TEST(Bc1Test, BestComesWithinAHundredthOfCrunchOnPhotographs) {
  const double crunch[] = {33.963, 35.672, 37.039, 38.987, 32.270};  // photographCrops' order
  const std::vector<Image> photos = test::photographCrops(256);
  ASSERT_EQ(photos.size(), std::size(crunch));
  double best = 0.0, theirs = 0.0;
  for (std::size_t i = 0; i < photos.size(); ++i) {
    const double psnr = test::decodedPsnr(photos[i], ours(photos[i], CompressionQuality::Best));
    std::printf("BC1 best on crop %zu: %.3f dB, crunch %.3f dB\n", i, psnr, crunch[i]);
    EXPECT_GE(psnr, crunch[i] - 0.05) << "crop " << i;
    best += psnr / double(photos.size());
    theirs += crunch[i] / double(photos.size());
  }
  EXPECT_GE(best, theirs - 0.02);
}

// Black, mid grey and white: four colours put mid grey 42 steps from its nearest palette entry
// (0, 85, 170, 255); three colours hold it at 127 (the half-way point, rounded down), one step.
TEST(Bc1Test, UsesTheThreeColourModeWhereItWins) {
  BlockTexels texels;
  for (int t = 0; t < 16; ++t) {
    const float v = t < 5 ? 0.0f : t < 11 ? 128.0f / 255.0f : 1.0f;
    texels[t][0] = texels[t][1] = texels[t][2] = v;
    texels[t][3] = 1.0f;
  }
  std::uint8_t block[8];
  encodeBcBlock(TextureFormat::Bc1, CompressionQuality::Best, false, texels, 0xFFFF, block);
  const int c0 = block[0] | block[1] << 8, c1 = block[2] | block[3] << 8;
  EXPECT_LE(c0, c1) << "the three-colour mode is c0 <= c1";
  BlockTexels decoded;
  decodeBcBlock(TextureFormat::Bc1, block, decoded);
  for (int t = 0; t < 16; ++t) {
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(decoded[t][c] * 255.0f, texels[t][c] * 255.0f, 1.01f) << t;
  }
}

// Grey ramps and photographs: wherever a block is in the three-colour mode, no texel takes
// index 3 (transparent black to a reader that gives DXT1 1-bit alpha).
TEST(Bc1Test, NeverUsesTransparentBlack) {
  std::vector<Image> maps = test::photographCrops(128);
  for (const Image& map : maps) {
    for (CompressionQuality quality :
         {CompressionQuality::Fast, CompressionQuality::Normal, CompressionQuality::Best}) {
      const CompressedTexture texture = ours(map, quality);
      const std::vector<std::uint8_t>& data = texture.levels[0].data;
      int threeColour = 0;
      for (std::size_t b = 0; b < data.size(); b += 8) {
        const int c0 = data[b] | data[b + 1] << 8, c1 = data[b + 2] | data[b + 3] << 8;
        if (c0 > c1)
          continue;
        ++threeColour;
        for (int t = 0; t < 16; ++t)
          ASSERT_NE((data[b + 4 + std::size_t(t / 4)] >> (2 * (t % 4))) & 3, 3);
      }
      if (quality == CompressionQuality::Best) {
        EXPECT_GT(threeColour, 0) << "photographs have blocks where three colours win";
      }
    }
  }
}

// Every flat grey and flat pure colour through the single-colour tables: BC1 reaches each 8-bit
// value within one step at a one-third point (measured: at most 1), BC3's colour half too.
TEST(Bc1Test, FlatColoursComeWithinOneStep) {
  for (TextureFormat format : {TextureFormat::Bc1, TextureFormat::Bc3}) {
    float worst = 0.0f;
    for (int v = 0; v < 256; ++v) {
      for (int pattern = 0; pattern < 2; ++pattern) {
        BlockTexels texels;
        for (auto& texel : texels) {
          texel[0] = float(v) / 255.0f;
          texel[1] = pattern ? float(255 - v) / 255.0f : texel[0];
          texel[2] = pattern ? float((v * 3) % 256) / 255.0f : texel[0];
          texel[3] = 1.0f;
        }
        std::uint8_t block[16];
        encodeBcBlock(format, CompressionQuality::Normal, false, texels, 0xFFFF, block);
        BlockTexels decoded;
        decodeBcBlock(format, block, decoded);
        for (int t = 0; t < 16; ++t) {
          for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(decoded[t][c] - texels[t][c]) * 255.0f);
        }
      }
    }
    EXPECT_LE(worst, 1.01f) << textureFormatInfo(format).name;
  }
}

// Luminance weights move error from green into red and blue: lower luminance-weighted error,
// lower uniform PSNR, than uniform weights on the same photograph.
TEST(Bc1Test, PerceptualWeightsFavourLuminance) {
  const Image photo = test::photographCrops(128).at(0);
  const auto weighted = [&](const CompressedTexture& texture) {
    const ImageError error = measureImageError(photo, decodeAsMap(texture).value());
    return 0.2126 * error.channels[0].mse + 0.7152 * error.channels[1].mse +
           0.0722 * error.channels[2].mse;
  };
  const CompressedTexture uniform = ours(photo, CompressionQuality::Normal, false);
  const CompressedTexture perceptual = ours(photo, CompressionQuality::Normal, true);
  EXPECT_LT(weighted(perceptual), weighted(uniform));
  EXPECT_GT(test::decodedPsnr(photo, uniform), test::decodedPsnr(photo, perceptual));
}

}  // namespace
}  // namespace relief::core
