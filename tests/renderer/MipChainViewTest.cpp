// Looking at a material from far away (renderer/FrameSettings.h: TilePreview::distance and
// FrameSettings::mipChains): the viewport samples the mip chain the map ships with, original or
// compressed, as an engine samples it there. A one-texel black and white checker seen from 16
// times farther shades as its mean in linear light (the colour a gamma-correct chain holds, not
// the 50% grey an sRGB-blind average gives); without mipmaps it aliases into noise; and the wipe
// between the original and a compressed preview compares the two chains at that distance.
#include "core/compression/Compressor.h"
#include "core/image/ColorSpace.h"
#include "core/mesh/MeshPrimitives.h"
#include "support/OffscreenFixture.h"

#include <cmath>
#include <memory>

namespace relief::test {
namespace {

constexpr int kSize = 256;
constexpr int kFarther = 16;  // 64 texels x 16 over ~256 pixels: mip level 2 and up

core::Image checker() {
  core::Image image(64, 64, 3);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      for (int c = 0; c < 3; ++c)
        image.at(x, y, c) = float((x + y) % 2);
    }
  }
  return image;
}

core::Image uniform(float value) {
  core::Image image(64, 64, 3);
  for (std::size_t i = 0; i < image.valueCount(); ++i)
    image.data()[i] = value;
  return image;
}

core::Material colourMaterial(const core::Image& colour) {
  core::Material material;
  material.setMap(core::MapSlot::Color, std::make_shared<const core::Image>(colour));
  return material;
}

// The mean and standard deviation of the red channel over [x0, x1) x [y0, y1).
struct Stats {
  double mean = 0.0;
  double deviation = 0.0;
};
Stats regionStats(const core::Image& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0, squares = 0.0;
  const double count = double(x1 - x0) * double(y1 - y0);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      sum += image.at(x, y, 0);
      squares += double(image.at(x, y, 0)) * image.at(x, y, 0);
    }
  }
  const double mean = sum / count;
  return {mean, std::sqrt(std::max(0.0, squares / count - mean * mean))};
}

class MipChainView : public OffscreenTest {
 protected:
  core::Image render(const core::Material& material, core::MipChainSpec chain = {},
                     std::optional<renderer::SplitComparison> split = std::nullopt) {
    const core::Mesh mesh = core::makePlane();
    offscreen().setMesh(mesh);
    offscreen().setMaterial(material);
    renderer::FrameSettings frame;
    frame.view.camera.pitchDeg = 89.0f;  // straight down on the plane: one LOD everywhere
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.frame(mesh.bounds(), 1.0f);
    frame.tiles.distance = kFarther;
    frame.mipChains[std::size_t(core::MapSlot::Color)] = chain;
    frame.split = std::move(split);
    core::Result<core::Image> image = offscreen().render(frame, kSize, kSize);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : core::Image();
  }

  static core::Material compressed(const core::Image& colour, bool mipmaps) {
    core::Material material = colourMaterial(colour);
    auto texture = std::make_shared<core::CompressedTexture>(
        core::compressMap(*material.image(core::MapSlot::Color), core::MapSlot::Color,
                          {core::TextureFormat::Bc1, core::CompressionQuality::Normal, mipmaps})
            .value());
    auto decoded = std::make_shared<core::Image>(core::decodeAsMap(*texture).value());
    material.setCompressedMap(core::MapSlot::Color, std::move(texture), std::move(decoded));
    return material;
  }
};

// The centre of the frame, away from the plane's edges.
constexpr int kLow = kSize / 4, kHigh = 3 * kSize / 4;

TEST_F(MipChainView, DistantCheckerShadesAsItsLinearLightMean) {
  const core::Image far = render(colourMaterial(checker()));
  const core::Image mean = render(colourMaterial(uniform(core::linearToSrgb(0.5f))));
  const core::Image naive = render(colourMaterial(uniform(0.5f)));
  const Stats farStats = regionStats(far, kLow, kHigh, kLow, kHigh);
  const Stats meanStats = regionStats(mean, kLow, kHigh, kLow, kHigh);
  EXPECT_NEAR(farStats.mean, meanStats.mean, 1.5 / 255.0);
  EXPECT_LT(farStats.deviation, 1.5 / 255.0) << "levels 2 and up of the checker are flat";
  EXPECT_GT(farStats.mean - regionStats(naive, kLow, kHigh, kLow, kHigh).mean, 20.0 / 255.0)
      << "an average of the sRGB codes would be visibly darker";
}

TEST_F(MipChainView, WithoutMipmapsTheDistantCheckerAliases) {
  const Stats chained = regionStats(render(colourMaterial(checker())), kLow, kHigh, kLow, kHigh);
  const Stats single = regionStats(render(colourMaterial(checker()), {false, core::MipFilter::Box}),
                                   kLow, kHigh, kLow, kHigh);
  EXPECT_LT(chained.deviation, 1.5 / 255.0);
  EXPECT_GT(single.deviation, 0.1) << "level 0 alone, 4 texels a pixel: the checker breaks up";
}

// The wipe: original left, compressed preview right, both from 16 times farther. BC1 with
// mipmaps ships the flat levels (within its 5:6:5 endpoints), so the halves match; BC1 without
// mipmaps ships level 0 alone, and its half aliases while the original's stays flat.
TEST_F(MipChainView, TheWipeComparesTheShippedChainsFarAway) {
  const core::Material original = colourMaterial(checker());
  const core::Image withMips =
      render(original, {}, renderer::SplitComparison{compressed(checker(), true), 0.5f});
  const Stats left = regionStats(withMips, kLow, kSize / 2 - 8, kLow, kHigh);
  const Stats right = regionStats(withMips, kSize / 2 + 8, kHigh, kLow, kHigh);
  EXPECT_NEAR(left.mean, right.mean, 3.0 / 255.0);
  EXPECT_LT(right.deviation, 1.5 / 255.0);
  const core::Image withoutMips =
      render(original, {}, renderer::SplitComparison{compressed(checker(), false), 0.5f});
  EXPECT_LT(regionStats(withoutMips, kLow, kSize / 2 - 8, kLow, kHigh).deviation, 1.5 / 255.0);
  EXPECT_GT(regionStats(withoutMips, kSize / 2 + 8, kHigh, kLow, kHigh).deviation, 0.1);
}

}  // namespace
}  // namespace relief::test
