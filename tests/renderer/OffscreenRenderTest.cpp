// Offscreen rendering: any size up to the GPU's limit, refusal beyond it, and the same picture
// for the same inputs.
#include "core/mesh/MeshPrimitives.h"
#include "support/ImageCompare.h"
#include "support/OffscreenFixture.h"

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

}  // namespace
}  // namespace relief::test
