// Offscreen rendering: any size up to the GPU's limit, refusal beyond it, and the same picture
// for the same inputs.
#include "core/mesh/MeshPrimitives.h"
#include "support/ImageCompare.h"
#include "support/OffscreenFixture.h"

#include <algorithm>
#include <cmath>

namespace relief::test {
namespace {

class OffscreenRender : public OffscreenTest {};

TEST_F(OffscreenRender, RendersOddSizesAndTinyOnes) {
  offscreen().setMesh(core::makeSphere());
  offscreen().setMaterial(core::Material());
  for (auto [width, height] : {std::pair{1, 1}, std::pair{37, 23}, std::pair{513, 7}}) {
    core::Result<core::Image> image = offscreen().render(renderer::RenderView(), width, height);
    ASSERT_TRUE(image.ok()) << image.error();
    EXPECT_EQ(image->width(), width);
    EXPECT_EQ(image->height(), height);
    EXPECT_EQ(image->channels(), 4);
    EXPECT_EQ(image->colorSpace(), core::ColorSpace::Srgb);
  }
}

TEST_F(OffscreenRender, RefusesSizesBeyondTheLimitWithAMessage) {
  const int tooBig = offscreen().maxSize() + 1;
  core::Result<core::Image> image = offscreen().render(renderer::RenderView(), tooBig, 16);
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.error().find(std::to_string(tooBig)), std::string::npos) << image.error();
  EXPECT_FALSE(offscreen().render(renderer::RenderView(), 0, 16).ok());
}

TEST_F(OffscreenRender, TheSphereIsCentredAndTheBackgroundIsOutside) {
  offscreen().setMesh(core::makeSphere());
  offscreen().setMaterial(core::Material());
  renderer::RenderView view;
  view.camera.frame(core::makeSphere().bounds(), 1.0f);
  core::Result<core::Image> image = offscreen().render(view, 64, 64);
  ASSERT_TRUE(image.ok());
  // Background corners are the dark gradient; the centre is the lit grey default material.
  const float corner = image->at(0, 0, 0);
  const float centre = image->at(32, 32, 0);
  EXPECT_LT(corner, 0.35f);
  EXPECT_GT(centre, corner + 0.1f);
}

TEST_F(OffscreenRender, SameInputsGiveTheSamePixels) {
  offscreen().setMesh(core::makeCube());
  offscreen().setMaterial(core::Material());
  core::Result<core::Image> first = offscreen().render(renderer::RenderView(), 96, 64);
  core::Result<core::Image> second = offscreen().render(renderer::RenderView(), 96, 64);
  ASSERT_TRUE(first.ok() && second.ok());
  EXPECT_EQ(compareImages(first.value(), second.value()).maxError, 0.0);
}

// Progressive refinement (the viewport once the input rests after reduced frames): the full
// frame drawn in bands of rows over the stretched reduced frame. Refined rows are the full
// frame's bits; rows not yet refined still show the reduced frame; every band drawn gives the
// full frame exactly, whatever the band height.
TEST_F(OffscreenRender, RefiningAReducedFrameInBandsGivesTheFullFrame) {
  offscreen().setMesh(core::makeSphere());
  core::Material material;
  material.setTechnique(core::Technique::Pom);
  offscreen().setMaterial(material);
  renderer::FrameSettings frame;
  frame.view.camera.frame(core::makeSphere().bounds(), 1.5f);
  constexpr int kWidth = 120, kHeight = 80;
  core::Result<core::Image> full = offscreen().render(frame, kWidth, kHeight);
  core::Result<core::Image> reduced = offscreen().render(frame, kWidth, kHeight, 0.25f);
  // Bands of 30 rows: three of them cover the 80 rows (the last one 20).
  core::Result<core::Image> refined =
      offscreen().render(frame, kWidth, kHeight, 0.25f, renderer::FrameRefinement{30, 3});
  core::Result<core::Image> half =
      offscreen().render(frame, kWidth, kHeight, 0.25f, renderer::FrameRefinement{40, 1});
  ASSERT_TRUE(full.ok() && reduced.ok() && refined.ok() && half.ok());
  EXPECT_EQ(compareImages(refined.value(), full.value()).maxError, 0.0);
  ASSERT_GT(compareImages(reduced.value(), full.value()).maxError, 8.0 / 255.0);
  double topError = 0.0, bottomError = 0.0;
  for (int y = 0; y < kHeight; ++y) {
    const core::Image& expected = y < kHeight / 2 ? full.value() : reduced.value();
    double& worst = y < kHeight / 2 ? topError : bottomError;
    for (int x = 0; x < kWidth; ++x) {
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, double(std::abs(half->at(x, y, c) - expected.at(x, y, c))));
    }
  }
  EXPECT_EQ(topError, 0.0) << "the refined top half is the full frame";
  EXPECT_EQ(bottomError, 0.0) << "the rest still shows the reduced frame";
}

// An interactive frame (MaterialRenderer::renderReduced) is the frame drawn at the reduced size,
// then stretched with bilinear filtering: each stretched pixel is the bilinear interpolation of
// the small frame at its centre, (x + 0.5) / 2 - 0.5 in the small frame's texels at scale 1/2.
// Tolerance: the blit rounds to 8 bits once more (1/255) and GL allows the filter a few bits of
// weight precision; 2.5/255 covers both.
TEST_F(OffscreenRender, AReducedFrameIsTheSmallFrameStretchedBilinearly) {
  offscreen().setMesh(core::makeSphere());
  offscreen().setMaterial(core::Material());
  renderer::FrameSettings frame;
  frame.view.camera.frame(core::makeSphere().bounds(), 1.5f);
  constexpr int kWidth = 120, kHeight = 80;
  core::Result<core::Image> small = offscreen().render(frame, kWidth / 2, kHeight / 2);
  core::Result<core::Image> stretched = offscreen().render(frame, kWidth, kHeight, 0.5f);
  ASSERT_TRUE(small.ok() && stretched.ok());
  ASSERT_EQ(stretched->width(), kWidth);
  const auto smallAt = [&](int x, int y, int channel) {
    return small->at(std::clamp(x, 0, kWidth / 2 - 1), std::clamp(y, 0, kHeight / 2 - 1), channel);
  };
  double worst = 0.0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float u = (float(x) + 0.5f) / 2.0f - 0.5f;
      const float v = (float(y) + 0.5f) / 2.0f - 0.5f;
      const int x0 = int(std::floor(u)), y0 = int(std::floor(v));
      const float fx = u - float(x0), fy = v - float(y0);
      for (int c = 0; c < 3; ++c) {
        const float expected =
            (1 - fy) * ((1 - fx) * smallAt(x0, y0, c) + fx * smallAt(x0 + 1, y0, c)) +
            fy * ((1 - fx) * smallAt(x0, y0 + 1, c) + fx * smallAt(x0 + 1, y0 + 1, c));
        worst = std::max(worst, double(std::abs(stretched->at(x, y, c) - expected)));
      }
    }
  }
  EXPECT_LE(worst, 2.5 / 255.0);
  // And it is not simply the full frame: the sphere's silhouette is softer.
  core::Result<core::Image> full = offscreen().render(frame, kWidth, kHeight);
  ASSERT_TRUE(full.ok());
  EXPECT_GT(compareImages(full.value(), stretched.value()).maxError, 8.0 / 255.0);
}

TEST_F(OffscreenRender, ReducedFramesAreForDisplayOnly) {
  renderer::FrameSettings frame;
  frame.output = renderer::FrameOutput::FloatData;
  core::Result<core::Image> image = offscreen().render(frame, 64, 64, 0.5f);
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.error().find("display"), std::string::npos) << image.error();
}

}  // namespace
}  // namespace relief::test
