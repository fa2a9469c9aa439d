// Mirrored UVs (reference 004's tangent.w): on a plane whose right half has u mirrored, the
// parallax offset must point away from the viewer in world space on both halves, so it has
// opposite signs in u and the same sign in v.
#include "core/mesh/Mesh.h"
#include "core/mesh/TangentFrames.h"
#include "support/OffscreenFixture.h"
#include "support/TestMeshes.h"

namespace relief::test {
namespace {

using core::Image;

class Handedness : public OffscreenTest {};

TEST_F(Handedness, ParallaxShiftsAwayFromTheViewerOnBothHalves) {
  // A flat field sunk below the surface: every visible point lies beyond the fragment, away
  // from the eye. Kaneko's offset is then exact, so only directions are being tested.
  core::Material material;
  auto floor = std::make_shared<Image>(8, 8, 1);  // all zero: the deepest level
  material.setMap(core::MapSlot::Height, floor);
  material.setTechnique(core::Technique::Parallax);
  material.setParameter(core::ParamId::HeightScale, 0.05);
  material.setParameter(core::ParamId::HeightBias, -0.05);
  offscreen().setMesh(test::mirroredQuads());
  offscreen().setMaterial(material);

  renderer::FrameSettings frame;
  frame.view.camera.yawDeg = 0.0f;  // the camera is on the +Z side, looking toward -Z
  frame.view.camera.pitchDeg = 45.0f;
  frame.view.camera.distance = 3.5f;
  frame.debugView = core::DebugView::Offset;
  frame.output = renderer::FrameOutput::FloatData;
  auto offsets = offscreen().render(frame, 200, 120);
  ASSERT_TRUE(offsets.ok()) << offsets.error();

  // A row through the middle; one column inside each half, mirror images of each other.
  const int y = 60;
  const float* left = offsets->pixel(60, y);    // left half: u grows with world X
  const float* right = offsets->pixel(140, y);  // right half: u shrinks with world X
  ASSERT_GT(left[3], 0.0f);
  ASSERT_GT(right[3], 0.0f);
  // Away from the viewer is world -Z everywhere, which is +v on both halves. The relief is
  // 0.05 of the mesh's world units per UV deep (core::worldUnitsPerUv: sqrt(4 / 2), each half
  // mapping UV 0..1 over 1 x 2 units), and Kaneko's offset at 45 degrees moves the point seen
  // as far along the surface: 0.0707 units, which v (2 units long) covers in 0.0354, 0.28
  // texels of the 8-texel map. (With the tangent frame's unit axes the depth followed v's
  // length instead, 0.4 texels.)
  const float expectedTexels =
      0.05f * float(core::worldUnitsPerUv(test::mirroredQuads())) / 2.0f * 8.0f;
  EXPECT_NEAR(expectedTexels, 0.283f, 0.001f);
  EXPECT_NEAR(left[1], expectedTexels, 0.03f);
  EXPECT_NEAR(right[1], expectedTexels, 0.03f);
  // Left of centre the eye ray also runs toward -X (world), right of centre toward +X. In
  // texture u that is negative on the left half and, mirrored, negative on the right too.
  EXPECT_LT(left[0], 0.0f);
  EXPECT_LT(right[0], 0.0f);
  // And symmetric: the two halves mirror each other.
  EXPECT_NEAR(left[0], right[0], 0.05f * std::abs(left[0]) + 1e-3f);
  EXPECT_NEAR(left[1], right[1], 0.05f * std::abs(left[1]) + 1e-3f);
}

}  // namespace
}  // namespace relief::test
