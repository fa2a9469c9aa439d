// The view's tile preview (renderer/FrameSettings.h, TilePreview): N repeats render exactly what
// the material's tiling times N renders (the preview changes the view, not the material), and
// the seam lines are thin amber lines where the map's edges are, nowhere else.
#include "core/image/ImageIO.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "support/OffscreenFixture.h"
#include "support/TestPaths.h"

#include <cmath>

namespace relief::test {
namespace {

constexpr int kSize = 256;

class TilePreview : public OffscreenTest {
 protected:
  core::Image render(const core::Material& material, renderer::TilePreview tiles) {
    const core::Mesh mesh = core::makePlane();
    offscreen().setMesh(mesh);
    offscreen().setMaterial(material);
    renderer::FrameSettings frame;
    frame.view.camera.pitchDeg = 89.0f;  // looking straight down on the plane
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.frame(mesh.bounds(), 1.0f);
    frame.tiles = tiles;
    core::Result<core::Image> image = offscreen().render(frame, kSize, kSize);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : core::Image();
  }
};

core::Material bricks() {
  core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset("bricks"));
  EXPECT_TRUE(preset.ok()) << preset.error();
  return preset.ok() ? preset->preset.material : core::Material();
}

TEST_F(TilePreview, RepeatsAreTheMaterialsTilingTimesN) {
  core::Material material = bricks();
  material.setParameter(core::ParamId::Tiling, 1.0);
  const core::Image previewed = render(material, {3, false});
  material.setParameter(core::ParamId::Tiling, 3.0);
  const core::Image tiled = render(material, {1, false});
  double worst = 0.0;
  for (std::size_t i = 0; i < tiled.valueCount(); ++i)
    worst = std::max(worst, double(std::abs(tiled.data()[i] - previewed.data()[i])));
  EXPECT_LE(worst, 1.0 / 255.0);
  EXPECT_NE(render(material, {2, false}), tiled) << "the repeats do change the view";
}

TEST_F(TilePreview, SeamLinesAreThinAmberLinesAtTheMapsEdges) {
  core::Material material = bricks();
  material.setParameter(core::ParamId::Tiling, 1.0);
  const core::Image plain = render(material, {2, false});
  const core::Image lined = render(material, {2, true});
  int changed = 0, amber = 0, covered = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const float* a = plain.pixel(x, y);
      const float* b = lined.pixel(x, y);
      if (plain.channels() == 4 && a[3] < 0.5f)
        continue;  // background
      ++covered;
      if (std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]) < 3.0f / 255.0f)
        continue;
      ++changed;
      if (b[0] > b[1] && b[1] > b[2] && b[0] > 0.6f)
        ++amber;
    }
  }
  ASSERT_GT(covered, kSize * kSize / 4);
  // Two repeats seen from above: the lines across the middle and along the plane's edges, a
  // few pixels wide each; a tenth of the covered pixels at most.
  EXPECT_GT(changed, kSize);
  EXPECT_LT(changed, covered / 10);
  EXPECT_GT(amber, changed * 3 / 4);
}

}  // namespace
}  // namespace relief::test
