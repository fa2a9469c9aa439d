// Golden images of the bundled samples, rendered through the same path as the viewport and
// `relief-cli render`. Baselines live in tests/baselines/ (RELIEF_UPDATE_BASELINES=1 rewrites
// them after an intended change; look at the new images before committing them).
#include "core/material/MaterialPreset.h"
#include "core/mesh/MeshPrimitives.h"
#include "support/ImageCompare.h"
#include "support/OffscreenFixture.h"
#include "support/TestPaths.h"

namespace relief::test {
namespace {

// Rasterisation and texture filtering differ slightly between GPUs and driver versions: a few
// edge pixels may move by one pixel (large max error) while the image as a whole must stay
// within half a level on average. On the same llvmpipe the images match exactly.
constexpr double kMaxTolerance = 64.0 / 255.0;
constexpr double kMeanTolerance = 0.5 / 255.0;

class SampleRender : public OffscreenTest {
 protected:
  core::Image render(const std::string& sample, core::PrimitiveShape shape) {
    core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset(sample));
    EXPECT_TRUE(preset.ok()) << preset.error();
    const core::Mesh mesh = core::makePrimitive(shape);
    offscreen().setMesh(mesh);
    offscreen().setMaterial(preset->preset.material);
    renderer::RenderView view;
    view.camera = core::defaultCameraFor(mesh, 320.0f / 200.0f);
    core::Result<core::Image> image = offscreen().render(view, 320, 200);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : core::Image();
  }
};

TEST_F(SampleRender, BricksOnThePlaneMatchTheBaseline) {
  EXPECT_TRUE(matchesBaseline(render("bricks", core::PrimitiveShape::Plane), "bricks_plane",
                              kMaxTolerance, kMeanTolerance));
}

TEST_F(SampleRender, CobblestonesOnTheSphereMatchTheBaseline) {
  EXPECT_TRUE(matchesBaseline(render("cobblestones", core::PrimitiveShape::Sphere),
                              "cobblestones_sphere", kMaxTolerance, kMeanTolerance));
}

TEST_F(SampleRender, TilesOnTheCubeMatchTheBaseline) {
  EXPECT_TRUE(matchesBaseline(render("tiles", core::PrimitiveShape::Cube), "tiles_cube",
                              kMaxTolerance, kMeanTolerance));
}

TEST_F(SampleRender, EveryTechniqueMatchesItsBaseline) {
  // Close and low over the cobblestones, where the techniques differ most.
  core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset("cobblestones"));
  ASSERT_TRUE(preset.ok()) << preset.error();
  // The editor's plane, whose grid displacement can tessellate to the texels.
  offscreen().setMesh(core::makePrimitive(core::PrimitiveShape::Plane));
  renderer::RenderView view;
  view.camera.yawDeg = 10.0f;
  view.camera.pitchDeg = 22.0f;
  view.camera.distance = 1.0f;
  for (core::Technique technique : core::allTechniques()) {
    core::Material material = preset->preset.material;
    material.setTechnique(technique);
    offscreen().setMaterial(material);
    core::Result<core::Image> image = offscreen().render(view, 256, 160);
    ASSERT_TRUE(image.ok()) << image.error();
    EXPECT_TRUE(matchesBaseline(image.value(),
                                "technique_" + std::string(core::techniqueName(technique)),
                                kMaxTolerance, kMeanTolerance));
  }
}

TEST_F(SampleRender, NormalMapChangesThePicture) {
  // Guards against a baseline that silently shows an unlit or flat surface: the sample with
  // its normal map must differ clearly from the same sample with the normal map removed.
  // Cobblestones: their domes slope almost everywhere, so the normal map touches most pixels.
  const core::Image withNormals = render("cobblestones", core::PrimitiveShape::Plane);
  core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset("cobblestones"));
  ASSERT_TRUE(preset.ok());
  preset->preset.material.clearMap(core::MapSlot::Normal);
  offscreen().setMaterial(preset->preset.material);
  renderer::RenderView view;
  view.camera = core::defaultCameraFor(core::makePlane(), 320.0f / 200.0f);
  core::Result<core::Image> flat = offscreen().render(view, 320, 200);
  ASSERT_TRUE(flat.ok());
  // Compare the middle of the frame, which the plane covers, not the background.
  auto middle = [](const core::Image& image) {
    core::Image crop(image.width() / 3, image.height() / 3, image.channels());
    for (int y = 0; y < crop.height(); ++y) {
      for (int x = 0; x < crop.width(); ++x) {
        for (int c = 0; c < crop.channels(); ++c) {
          crop.at(x, y, c) = image.at(x + image.width() / 3, y + image.height() / 3, c);
        }
      }
    }
    return crop;
  };
  EXPECT_GT(compareImages(middle(withNormals), middle(flat.value())).meanError, 6.0 / 255.0);
}

}  // namespace
}  // namespace relief::test
