// Self-shadowing (reference 003, 1.3): a tall box casts its shadow away from the light and
// none toward it, hard shadows agree with the exact shadow ray of the reference tracer, and
// strength 0 is the same picture as shadows off.
#include "core/mesh/MeshPrimitives.h"
#include "core/tracing/ReliefTracer.h"
#include "support/ImageCompare.h"
#include "support/OffscreenFixture.h"

namespace relief::test {
namespace {

using core::Image;
using core::ParamId;

constexpr int kSize = 64;
constexpr double kScale = 0.1;

// A 16x16-texel box of height 1 on a floor at 0, in the middle of the map.
Image boxField() {
  Image field(kSize, kSize, 1);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      field.at(x, y, 0) = (x >= 24 && x < 40 && y >= 24 && y < 40) ? 1.0f : 0.0f;
    }
  }
  return field;
}

class SelfShadow : public OffscreenTest {
 protected:
  core::Material boxMaterial(core::ShadowMode mode, double strength) {
    core::Material material;
    material.setMap(core::MapSlot::Height, std::make_shared<Image>(boxField()));
    material.setTechnique(core::Technique::Relief);
    material.setParameter(ParamId::HeightScale, kScale);
    material.setParameter(ParamId::HeightBias, -kScale);
    material.setParameter(ParamId::MinSamples, 64);
    material.setParameter(ParamId::MaxSamples, 64);
    material.setParameter(ParamId::ShadowMode, double(mode));
    material.setParameter(ParamId::ShadowStrength, strength);
    material.setParameter(ParamId::ShadowSamples, 128);
    material.setParameter(ParamId::ShadowLimit, 0.0);
    return material;
  }

  // Straight down on the plane; the light comes from +X (tangent +u), 30 degrees up.
  renderer::FrameSettings frame(core::DebugView view, renderer::FrameOutput output) {
    renderer::FrameSettings settings;
    settings.view.camera.yawDeg = 0.0f;
    settings.view.camera.pitchDeg = 89.0f;
    settings.view.camera.distance = 2.6f;
    settings.view.light.azimuthDeg = 90.0f;
    settings.view.light.elevationDeg = 30.0f;
    settings.debugView = view;
    settings.output = output;
    return settings;
  }
};

TEST_F(SelfShadow, ABoxShadowsTheSideAwayFromTheLightOnly) {
  offscreen().setMesh(core::makePlane());
  offscreen().setMaterial(boxMaterial(core::ShadowMode::Hard, 1.0));
  const int size = 256;
  auto lit = offscreen().render(frame(core::DebugView::Shadow, renderer::FrameOutput::FloatData),
                                size, size);
  auto uv =
      offscreen().render(frame(core::DebugView::Uv, renderer::FrameOutput::FloatData), size, size);
  ASSERT_TRUE(lit.ok() && uv.ok());
  // Sample the floor just beside the box's -u side (away from the light) and +u side.
  int shadowedAway = 0, litAway = 0, shadowedToward = 0, litToward = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (uv->at(x, y, 3) <= 0.0f)
        continue;
      const double u = uv->at(x, y, 0) * kSize, v = uv->at(x, y, 1) * kSize;
      if (v < 28 || v > 36)
        continue;
      const bool shadowed = lit->at(x, y, 0) < 0.5f;
      if (u > 19 && u < 23)
        (shadowed ? shadowedAway : litAway)++;
      if (u > 41 && u < 45)
        (shadowed ? shadowedToward : litToward)++;
    }
  }
  // Box height 0.1 UV = 6.4 texels at 30 degrees: a shadow 11 texels long on the far side.
  EXPECT_GT(shadowedAway, 20);
  EXPECT_EQ(litAway, 0);
  EXPECT_GT(litToward, 20);
  EXPECT_EQ(shadowedToward, 0);
}

TEST_F(SelfShadow, HardShadowsAgreeWithTheExactShadowRay) {
  offscreen().setMesh(core::makePlane());
  const core::Material material = boxMaterial(core::ShadowMode::Hard, 1.0);
  offscreen().setMaterial(material);
  const int size = 200;
  const auto settings = frame(core::DebugView::Shadow, renderer::FrameOutput::FloatData);
  auto lit = offscreen().render(settings, size, size);
  auto uv =
      offscreen().render(frame(core::DebugView::Uv, renderer::FrameOutput::FloatData), size, size);
  auto height = offscreen().render(frame(core::DebugView::Height, renderer::FrameOutput::FloatData),
                                   size, size);
  ASSERT_TRUE(lit.ok() && uv.ok() && height.ok());
  const core::HeightField field = core::HeightField::fromMaterial(material);
  // Tangent frame of the plane: T = +X, B = -Z, N = +Y; the light direction in it.
  const glm::dvec3 world = glm::dvec3(settings.view.light.direction());
  const glm::dvec3 lightTangent(world.x, -world.z, world.y);
  int agree = 0, total = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (uv->at(x, y, 3) <= 0.0f)
        continue;
      const double s = height->at(x, y, 0) * kScale - kScale;
      const core::ShadowRayHit exact =
          core::traceShadowRay(field, {uv->at(x, y, 0), uv->at(x, y, 1)}, s, lightTangent);
      agree += exact.occluded == (lit->at(x, y, 0) < 0.5f);
      ++total;
    }
  }
  ASSERT_GT(total, 10000);
  // Disagreement only in the one-texel bands where the field is a wall or a shadow edge.
  EXPECT_GT(double(agree) / total, 0.97) << agree << " of " << total;
}

TEST_F(SelfShadow, StrengthZeroEqualsShadowsOff) {
  offscreen().setMesh(core::makePlane());
  const auto settings = frame(core::DebugView::Shading, renderer::FrameOutput::Display);
  offscreen().setMaterial(boxMaterial(core::ShadowMode::Soft, 0.0));
  auto zero = offscreen().render(settings, 160, 160);
  offscreen().setMaterial(boxMaterial(core::ShadowMode::Off, 1.0));
  auto off = offscreen().render(settings, 160, 160);
  offscreen().setMaterial(boxMaterial(core::ShadowMode::Soft, 1.0));
  auto full = offscreen().render(settings, 160, 160);
  ASSERT_TRUE(zero.ok() && off.ok() && full.ok());
  EXPECT_EQ(compareImages(zero.value(), off.value()).maxError, 0.0);
  // And shadows do show: the light's share of a shadowed pixel goes (the environment's stays).
  EXPECT_GT(compareImages(full.value(), off.value()).maxError, 0.15);
}

TEST_F(SelfShadow, SoftShadowsHaveAPenumbraThatGrowsWithTheLightSize) {
  offscreen().setMesh(core::makePlane());
  const auto settings = frame(core::DebugView::Shadow, renderer::FrameOutput::FloatData);
  auto partial = [&](double softnessDeg) {
    core::Material material = boxMaterial(core::ShadowMode::Soft, 1.0);
    material.setParameter(ParamId::ShadowSoftness, softnessDeg);
    offscreen().setMaterial(material);
    auto lit = offscreen().render(settings, 200, 200);
    int count = 0;
    for (std::size_t p = 0; lit.ok() && p < lit->pixelCount(); ++p) {
      const float value = lit->data()[p * 4];
      count += lit->data()[p * 4 + 3] > 0.0f && value > 0.05f && value < 0.95f;
    }
    return count;
  };
  const int hardEdge = partial(0.0);
  const int small = partial(4.0);
  const int large = partial(20.0);
  EXPECT_EQ(hardEdge, 0);
  EXPECT_GT(small, 0);
  EXPECT_GT(large, 2 * small);
}

}  // namespace
}  // namespace relief::test
