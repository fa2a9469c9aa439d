// The mapping options against what they promise: depthOffset writes the depth of the displaced
// surface (exactly, on a flat sunken field), uvEdge clamp discards what is displaced outside
// the mesh's UV range, lodFade removes the relief beyond its mip level.
#include "core/mesh/MeshPrimitives.h"
#include "support/OffscreenFixture.h"

#include <cmath>

namespace relief::test {
namespace {

using core::Image;
using core::ParamId;

constexpr double kFlatScale = 0.05;

// A flat field at h = 0: with heightBias = -heightScale the surface lies kFlatScale UV below the
// mesh everywhere, so every technique's answer is known exactly.
core::Material sunkenMaterial(core::Technique technique) {
  core::Material material;
  material.setMap(core::MapSlot::Height, std::make_shared<Image>(16, 16, 1));
  material.setTechnique(technique);
  material.setParameter(ParamId::HeightScale, kFlatScale);
  material.setParameter(ParamId::HeightBias, -kFlatScale);
  material.setParameter(ParamId::ShadowMode, double(core::ShadowMode::Off));
  return material;
}

renderer::FrameSettings dataFrame(core::DebugView view, float pitch, float distance) {
  renderer::FrameSettings frame;
  frame.view.camera.yawDeg = 0.0f;
  frame.view.camera.pitchDeg = pitch;
  frame.view.camera.distance = distance;
  frame.debugView = view;
  frame.output = renderer::FrameOutput::FloatData;
  return frame;
}

class ReliefOptions : public OffscreenTest {};

TEST_F(ReliefOptions, DepthOffsetWritesTheDepthOfTheDisplacedSurface) {
  offscreen().setMesh(core::makePlane());  // 2 world units for 1 UV: one UV unit = 2 units
  core::Material material = sunkenMaterial(core::Technique::Pom);
  const float distance = 3.0f;
  const auto frame = dataFrame(core::DebugView::Depth, 89.0f, distance);
  offscreen().setMaterial(material);
  auto surface = offscreen().render(frame, 64, 64);
  material.setParameter(ParamId::DepthOffset, 1.0);
  offscreen().setMaterial(material);
  auto displaced = offscreen().render(frame, 64, 64);
  ASSERT_TRUE(surface.ok() && displaced.ok());
  // Straight down at the centre: the mesh is `distance` away, the sunken surface 2 * kFlatScale
  // world units further.
  EXPECT_NEAR(surface->at(32, 32, 0), distance, 0.01f);
  EXPECT_NEAR(displaced->at(32, 32, 0), distance + 2.0 * kFlatScale, 0.01f);
}

TEST_F(ReliefOptions, UvEdgeClampDiscardsWhatLeavesTheUvRange) {
  offscreen().setMesh(core::makePlane());
  core::Material material = sunkenMaterial(core::Technique::Parallax);
  const auto frame = dataFrame(core::DebugView::Uv, 30.0f, 3.2f);
  const auto render = [&](core::UvEdge edge) {
    material.setParameter(ParamId::UvEdge, double(edge));
    offscreen().setMaterial(material);
    return offscreen().render(frame, 160, 100);
  };
  auto repeat = render(core::UvEdge::Repeat);
  auto clamp = render(core::UvEdge::Clamp);
  ASSERT_TRUE(repeat.ok() && clamp.ok());
  long long repeatPixels = 0, clampPixels = 0, outside = 0;
  for (std::size_t p = 0; p < clamp->pixelCount(); ++p) {
    repeatPixels += repeat->data()[p * 4 + 3] > 0.0f;
    if (clamp->data()[p * 4 + 3] <= 0.0f)
      continue;
    ++clampPixels;
    const float u = clamp->data()[p * 4], v = clamp->data()[p * 4 + 1];
    outside += u < 0.0f || u > 1.0f || v < 0.0f || v > 1.0f;
  }
  EXPECT_EQ(outside, 0);
  // The near edge loses the band whose offset points beyond v = 0 or 1.
  EXPECT_LT(clampPixels, repeatPixels);
  EXPECT_GT(clampPixels, repeatPixels / 2);
}

TEST_F(ReliefOptions, LodFadeRemovesTheReliefBeyondItsMipLevel) {
  offscreen().setMesh(core::makePlane());
  core::Material material = sunkenMaterial(core::Technique::Pom);
  auto big = std::make_shared<Image>(1024, 1024, 1);  // many mip levels
  material.setMap(core::MapSlot::Height, big);
  material.setParameter(ParamId::LodFade, 4.0);
  offscreen().setMaterial(material);
  const auto offsetFrame = dataFrame(core::DebugView::Offset, 25.0f, 2.5f);
  auto offsets = offscreen().render(offsetFrame, 200, 120);
  auto mips = offscreen().render(dataFrame(core::DebugView::Mip, 25.0f, 2.5f), 200, 120);
  ASSERT_TRUE(offsets.ok() && mips.ok());
  int faded = 0, full = 0;
  for (std::size_t p = 0; p < offsets->pixelCount(); ++p) {
    if (offsets->data()[p * 4 + 3] <= 0.0f)
      continue;
    const float mip = mips->data()[p * 4];
    const float offset = std::hypot(offsets->data()[p * 4], offsets->data()[p * 4 + 1]);
    if (mip >= 4.0f) {
      EXPECT_EQ(offset, 0.0f) << "mip " << mip;
      ++faded;
    } else if (mip < 3.0f) {
      EXPECT_GT(offset, 0.1f) << "mip " << mip;
      ++full;
    }
  }
  EXPECT_GT(faded, 100);
  EXPECT_GT(full, 100);
}

}  // namespace
}  // namespace relief::test
