// Silhouettes on curved meshes (the curvedSilhouettes option, shaders/include/curved_march.glsl):
// on the sphere, with the relief carved into the surface (bias = -scale), the outline the
// marches draw against the tessellated displacement's, the geometric reference. Within 12
// pixels of the displaced outline, the covered pixels' intersection over union with the
// displaced mesh's must reach 0.85; plain POM, whose relief ends at the mesh's outline, is
// measured beside it. On the plane nothing changes: same picture, and UV clamping still cuts
// the relief's edge.
#include "core/mesh/MeshPrimitives.h"
#include "support/ImageCompare.h"
#include "support/OffscreenFixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace relief::test {
namespace {

using core::Image;
using core::ParamId;

constexpr int kSilhouetteWidth = 320;
constexpr int kSilhouetteHeight = 240;

Image studdedField() {
  // Square studs at the top on a floor at the bottom: most of the surface lies a full depth
  // under the mesh, so the displaced outline is inset everywhere but at the studs.
  constexpr int kFieldSize = 64;
  Image field(kFieldSize, kFieldSize, 1);
  for (int y = 0; y < kFieldSize; ++y) {
    for (int x = 0; x < kFieldSize; ++x)
      field.at(x, y, 0) = (x % 16 < 6 && y % 16 < 6) ? 1.0f : 0.0f;
  }
  return field;
}

core::Material carvedMaterial(core::Technique technique, bool silhouettes) {
  core::Material material;
  material.setMap(core::MapSlot::Height, std::make_shared<Image>(studdedField()));
  material.setTechnique(technique);
  material.setParameter(ParamId::HeightScale, 0.06);
  material.setParameter(ParamId::HeightBias, -0.06);
  material.setParameter(ParamId::Tiling, 2.0);
  material.setParameter(ParamId::MinSamples, 16);
  material.setParameter(ParamId::MaxSamples, 64);
  material.setParameter(ParamId::MaxTessellation, 64);
  material.setParameter(ParamId::ShadowMode, double(core::ShadowMode::Off));
  material.setParameter(ParamId::CurvedSilhouettes, silhouettes ? 1.0 : 0.0);
  return material;
}

class Silhouettes : public OffscreenTest {
 public:
  // Covered pixels of the material on `mesh` (alpha of the float uv view).
  std::vector<bool> coverage(const core::Material& material, const core::Mesh& mesh) {
    offscreen().setMesh(mesh);
    offscreen().setMaterial(material);
    renderer::FrameSettings frame;
    frame.view.camera.yawDeg = 30.0f;
    frame.view.camera.pitchDeg = 10.0f;
    frame.view.camera.distance = 2.6f;
    frame.debugView = core::DebugView::Uv;
    frame.output = renderer::FrameOutput::FloatData;
    core::Result<Image> image = offscreen().render(frame, kSilhouetteWidth, kSilhouetteHeight);
    EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error());
    std::vector<bool> covered(std::size_t(kSilhouetteWidth) * kSilhouetteHeight, false);
    if (!image.ok())
      return covered;
    for (int y = 0; y < kSilhouetteHeight; ++y) {
      for (int x = 0; x < kSilhouetteWidth; ++x)
        covered[std::size_t(y) * kSilhouetteWidth + std::size_t(x)] = image->at(x, y, 3) > 0.0f;
    }
    return covered;
  }
};

// Pixels within `radius` of the reference's outline (a covered pixel with an uncovered
// 4-neighbour).
std::vector<bool> outlineBand(const std::vector<bool>& reference, int radius) {
  const auto at = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < kSilhouetteWidth && y < kSilhouetteHeight &&
           reference[std::size_t(y) * kSilhouetteWidth + std::size_t(x)];
  };
  std::vector<bool> band(reference.size(), false);
  for (int y = 0; y < kSilhouetteHeight; ++y) {
    for (int x = 0; x < kSilhouetteWidth; ++x) {
      if (!at(x, y) || (at(x - 1, y) && at(x + 1, y) && at(x, y - 1) && at(x, y + 1)))
        continue;
      for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
          const int bx = x + dx, by = y + dy;
          if (dx * dx + dy * dy <= radius * radius && bx >= 0 && by >= 0 && bx < kSilhouetteWidth &&
              by < kSilhouetteHeight)
            band[std::size_t(by) * kSilhouetteWidth + std::size_t(bx)] = true;
        }
      }
    }
  }
  return band;
}

double bandIou(const std::vector<bool>& mask, const std::vector<bool>& reference,
               const std::vector<bool>& band) {
  long long both = 0, either = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!band[i])
      continue;
    both += mask[i] && reference[i] ? 1 : 0;
    either += mask[i] || reference[i] ? 1 : 0;
  }
  return either > 0 ? double(both) / double(either) : 0.0;
}

struct OutlineIou {
  double pom = 0.0, silhouette = 0.0, relief = 0.0;
};

OutlineIou measureOutline(Silhouettes& test, const core::Mesh& mesh, const char* name) {
  const std::vector<bool> displaced =
      test.coverage(carvedMaterial(core::Technique::Displacement, false), mesh);
  const std::vector<bool> band = outlineBand(displaced, 12);
  OutlineIou iou;
  iou.pom =
      bandIou(test.coverage(carvedMaterial(core::Technique::Pom, false), mesh), displaced, band);
  iou.silhouette =
      bandIou(test.coverage(carvedMaterial(core::Technique::Pom, true), mesh), displaced, band);
  iou.relief =
      bandIou(test.coverage(carvedMaterial(core::Technique::Relief, true), mesh), displaced, band);
  std::printf(
      "%s outline IoU within 12 px: POM %.3f, silhouette POM %.3f, silhouette relief "
      "%.3f\n",
      name, iou.pom, iou.silhouette, iou.relief);
  return iou;
}

// The marches give the relief the displacement's depth in world units (toUvHeightSpace: the
// mesh's one world-per-UV factor, the surface's own UV axes for the parallax), so the outlines
// agree on the cylinder, whose texels are near square, and on the sphere, whose texels are twice
// as wide as tall at the equator and squeezed to nothing at the poles (with the tangent frame's
// unit axes the marches carved a third deeper at the equator: silhouette POM reached 0.754).
// Measured on llvmpipe: cylinder POM 0.867, with silhouettes 0.919; sphere POM 0.713, with
// silhouettes 0.850 (0.842 with Oliveira and Policarpo's quadratic instead of the osculating
// circle, curved_march.glsl).
TEST_F(Silhouettes, CylinderOutlineFollowsTheDisplacedMesh) {
  const OutlineIou iou = measureOutline(*this, core::makeCylinder(), "cylinder");
  EXPECT_GE(iou.silhouette, 0.85);
  EXPECT_GE(iou.relief, 0.85);
  EXPECT_GT(iou.silhouette, iou.pom + 0.05);
}

TEST_F(Silhouettes, SphereOutlineFollowsTheDisplacedMesh) {
  const OutlineIou iou = measureOutline(*this, core::makeSphere(), "sphere");
  EXPECT_GE(iou.silhouette, 0.85);
  EXPECT_GE(iou.relief, 0.85);
  EXPECT_GT(iou.silhouette, iou.pom + 0.1);
}

TEST_F(Silhouettes, ThePlaneIsUnchangedAndItsClipKept) {
  offscreen().setMesh(core::makePlane());
  renderer::FrameSettings frame;
  frame.view.camera.pitchDeg = 25.0f;
  frame.view.camera.distance = 1.4f;
  for (bool clamp : {false, true}) {
    core::Material material = carvedMaterial(core::Technique::Pom, false);
    material.setParameter(ParamId::UvEdge,
                          double(clamp ? core::UvEdge::Clamp : core::UvEdge::Repeat));
    offscreen().setMaterial(material);
    core::Result<Image> plain = offscreen().render(frame, kSilhouetteWidth, kSilhouetteHeight);
    material.setParameter(ParamId::CurvedSilhouettes, 1.0);
    offscreen().setMaterial(material);
    core::Result<Image> curved = offscreen().render(frame, kSilhouetteWidth, kSilhouetteHeight);
    ASSERT_TRUE(plain.ok() && curved.ok());
    const ImageDifference difference = compareImages(plain.value(), curved.value());
    // The same march stepped in distance instead of height: the same surface, a texel's
    // rounding apart at most here and there.
    EXPECT_LT(difference.meanError, 0.5 / 255.0) << "clamp " << clamp;
  }
}

}  // namespace
}  // namespace relief::test
