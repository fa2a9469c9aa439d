// The view's tile preview (renderer/FrameSettings.h, TilePreview): N repeats render exactly what
// the material's tiling times N renders (the preview changes the view, not the material), the
// seam lines are thin amber lines where the map's edges are, nowhere else, and hex-tiling
// (shaders/include/hex_tiling.glsl) breaks the repetition while keeping the map's histogram.
#include "core/image/ImageIO.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/preset/MaterialPreset.h"
#include "renderer/ShaderVariant.h"
#include "support/OffscreenFixture.h"
#include "support/TestPaths.h"

#include <algorithm>
#include <cstdio>

#include <cmath>

namespace relief::test {
namespace {

constexpr int kSize = 256;

class TilePreview : public OffscreenTest {
 protected:
  core::Image render(const core::Material& material, renderer::TilePreview tiles,
                     core::DebugView view = core::DebugView::Shading) {
    const core::Mesh mesh = core::makePlane();
    offscreen().setMesh(mesh);
    offscreen().setMaterial(material);
    renderer::FrameSettings frame;
    frame.view.camera.pitchDeg = 89.0f;  // looking straight down on the plane
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.frame(mesh.bounds(), 1.0f);
    frame.tiles = tiles;
    frame.debugView = view;
    if (view != core::DebugView::Shading)
      frame.output = renderer::FrameOutput::FloatData;
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

// Mean and deviation of the first channel over the middle of the picture, and how close the
// picture comes to itself shifted by about one repeat of the map (the best of the shifts within
// 40% of kSize / repeats pixels across, two up or down): a plain tiling repeats, up to the
// view's slight perspective; hex-tiling should not.
struct HeightStatistics {
  double mean = 0.0, deviation = 0.0, repetition = 0.0;
};

HeightStatistics statistics(const core::Image& image, int period) {
  const int low = kSize / 8, high = kSize * 7 / 8;
  double sum = 0.0, squares = 0.0, count = 0.0;
  for (int y = low; y < high; ++y) {
    for (int x = low; x < high; ++x) {
      const double h = image.at(x, y, 0);
      sum += h;
      squares += h * h;
      count += 1.0;
    }
  }
  const double mean = sum / count;
  double best = 1e30;
  for (int dx = period * 6 / 10; dx <= period * 14 / 10; ++dx) {
    for (int dy = -2; dy <= 2; ++dy) {
      double shifted = 0.0, pairs = 0.0;
      for (int y = low + 2; y < high - 2; ++y) {
        for (int x = low; x + dx < high; ++x) {
          const double d = image.at(x, y, 0) - image.at(x + dx, y + dy, 0);
          shifted += d * d;
          pairs += 1.0;
        }
      }
      best = std::min(best, std::sqrt(shifted / pairs));
    }
  }
  return {mean, std::sqrt(squares / count - mean * mean), best};
}

TEST_F(TilePreview, HexTilingBreaksTheRepetitionAndKeepsTheHistogram) {
  core::Material material = bricks();
  material.setTechnique(core::Technique::Normal);  // the height view shows the map's heights
  material.setParameter(core::ParamId::Tiling, 1.0);
  constexpr int kRepeats = 8;
  const HeightStatistics plain = statistics(
      render(material, {kRepeats, false, false}, core::DebugView::Height), kSize / kRepeats);
  const HeightStatistics hex = statistics(
      render(material, {kRepeats, false, true}, core::DebugView::Height), kSize / kRepeats);
  std::printf("height mean %.4f -> %.4f, deviation %.4f -> %.4f, repetition %.4f -> %.4f\n",
              plain.mean, hex.mean, plain.deviation, hex.deviation, plain.repetition,
              hex.repetition);
  // The blend is mostly one copy (weights to the 7th power) with a thin border where the
  // taller texel wins: the histogram's mean moves a little up, its spread barely changes
  // (Mikkelsen 2022 keeps contrast where a linear blend would halve it).
  EXPECT_NEAR(hex.mean, plain.mean, 0.03);
  EXPECT_NEAR(hex.deviation / plain.deviation, 1.0, 0.1);
  // Seen from above, the plain tiling is its own copy one repeat further (up to the view's
  // slight perspective); hex-tiling is not.
  EXPECT_GT(hex.repetition, 3.0 * plain.repetition);
}

TEST_F(TilePreview, HexTilingAppliesWhereTheTechniqueCanTakeIt) {
  core::Material material = bricks();
  for (core::Technique technique : core::allTechniques()) {
    material.setTechnique(technique);
    const auto defines = renderer::materialShaderDefines(material, core::DebugView::Shading,
                                                         renderer::FrameOutput::Display, true);
    const bool hex = std::find(defines.begin(), defines.end(), "HEX_TILING") != defines.end();
    EXPECT_EQ(hex, core::supportsHexTiling(technique)) << core::techniqueName(technique);
  }
  material.setTechnique(core::Technique::Pom);
  EXPECT_FALSE(renderer::hexTilingApplies(material, core::DebugView::Error,
                                          renderer::FrameOutput::FloatData));
  material.setParameter(core::ParamId::UvEdge, double(int(core::UvEdge::Clamp)));
  EXPECT_FALSE(renderer::hexTilingApplies(material, core::DebugView::Shading,
                                          renderer::FrameOutput::Display));
}

}  // namespace
}  // namespace relief::test
