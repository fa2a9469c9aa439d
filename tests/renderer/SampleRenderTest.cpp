// Golden images of the bundled samples, rendered through the same path as the viewport and
// `relief-cli render`. Baselines live in tests/baselines/ (RELIEF_UPDATE_BASELINES=1 rewrites
// them after an intended change; look at the new images before committing them).
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "support/ImageCompare.h"
#include "support/OffscreenFixture.h"
#include "support/TestPaths.h"

#include <cstdio>

namespace relief::test {
namespace {

// Rasterisation and texture filtering differ slightly between GPUs and driver versions: a few
// edge pixels may move by one pixel (large max error) while the image as a whole must stay
// within half a level on average. On the same llvmpipe the images match exactly.
constexpr double kMaxTolerance = 64.0 / 255.0;
constexpr double kMeanTolerance = 0.5 / 255.0;

core::Image crop(const core::Image& image, int left, int top, int width, int height) {
  core::Image part(width, height, image.channels());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < image.channels(); ++c)
        part.at(x, y, c) = image.at(x + left, y + top, c);
    }
  }
  return part;
}

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

// Each shading model and built-in environment, on the bricks sphere seen from the default
// camera: classic (Blinn-Phong, the directional light and a constant ambient), and pbr under
// the overcast sky shown behind the material, under the uniform white, and as a smooth metal
// (metallic 1, roughness 0.25) under the studio with its blurred background. The studio with
// the plain backdrop is cobblestones_sphere above.
TEST_F(SampleRender, EachShadingAndEnvironmentMatchesItsBaseline) {
  core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset("bricks"));
  ASSERT_TRUE(preset.ok()) << preset.error();
  const core::Mesh mesh = core::makePrimitive(core::PrimitiveShape::Sphere);
  offscreen().setMesh(mesh);
  struct Case {
    const char* baseline;
    core::ShadingModel shading;
    const char* environment;
    core::Background background;
    float metallic, roughness;
  };
  const Case cases[] = {
      {"shading_classic", core::ShadingModel::Classic, "studio", core::Background::Color, 0, 0},
      {"environment_sky", core::ShadingModel::Pbr, "sky", core::Background::Environment, 0, 0.8f},
      {"environment_uniform", core::ShadingModel::Pbr, "uniform", core::Background::Color, 0, 0.8f},
      {"environment_studio_metal", core::ShadingModel::Pbr, "studio", core::Background::Blurred,
       1.0f, 0.25f},
  };
  for (const Case& c : cases) {
    core::Material material = preset->preset.material;
    material.setParameter(core::ParamId::Shading, double(int(c.shading)));
    material.setParameter(core::ParamId::Metallic, c.metallic);
    material.setParameter(core::ParamId::Roughness, c.roughness);
    offscreen().setMaterial(material);
    renderer::FrameSettings frame;
    frame.view.camera = core::defaultCameraFor(mesh, 240.0f / 160.0f);
    frame.view.environment.source = c.environment;
    frame.view.environment.background = c.background;
    core::Result<core::Image> image = offscreen().render(frame, 240, 160);
    ASSERT_TRUE(image.ok()) << image.error();
    EXPECT_TRUE(matchesBaseline(image.value(), c.baseline, kMaxTolerance, kMeanTolerance))
        << c.baseline;
  }
}

// The two exact tracers reach the same bilinear surface by different walks (the maximum-mipmap
// pyramid, cone steps), so where the height map is magnified their frames must agree: close
// over the cobblestones, looking down at 30 degrees. Where the map is minified both take the
// top of a pyramid block as the hit, but reach it from different points along the ray, so only
// the near third of the frame, where the map is magnified, is compared (on llvmpipe: mean
// 0.000, max 1/255 there; over the whole frame the mean is 0.17/255). The tolerance allows
// GPUs that filter with 8-bit weights.
TEST_F(SampleRender, ConeAndQuadtreeShowTheSameRelief) {
  core::Result<core::LoadedPreset> preset = core::loadPreset(samplePreset("cobblestones"));
  ASSERT_TRUE(preset.ok()) << preset.error();
  offscreen().setMesh(core::makePrimitive(core::PrimitiveShape::Plane));
  renderer::RenderView view;
  view.camera.yawDeg = 30.0f;
  view.camera.pitchDeg = 30.0f;
  view.camera.distance = 0.35f;
  core::Image frames[2];
  for (int i = 0; i < 2; ++i) {
    core::Material material = preset->preset.material;
    material.setTechnique(i == 0 ? core::Technique::Quadtree : core::Technique::Cone);
    offscreen().setMaterial(material);
    core::Result<core::Image> image = offscreen().render(view, 320, 200);
    ASSERT_TRUE(image.ok()) << image.error();
    // The bottom third: the near ground.
    frames[i] =
        crop(image.value(), 0, image->height() * 2 / 3, image->width(), image->height() / 3);
  }
  const ImageDifference difference = compareImages(frames[0], frames[1]);
  std::printf("cone against quadtree: mean %.5f, max %.4f\n", difference.meanError,
              difference.maxError);
  EXPECT_LT(difference.meanError, 0.25 / 255.0);
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
    return crop(image, image.width() / 3, image.height() / 3, image.width() / 3,
                image.height() / 3);
  };
  EXPECT_GT(compareImages(middle(withNormals), middle(flat.value())).meanError, 6.0 / 255.0);
}

}  // namespace
}  // namespace relief::test
