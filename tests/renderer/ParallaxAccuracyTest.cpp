// POM and relief mapping against the exact reference tracer (core/ReliefTracer), on a smooth
// and a stepped analytic height field, seen head-on and at a grazing angle. Errors are the
// renderer's final UV against the exact intersection for the same eye ray, in texels.
//
// The bounds are stated in layers: a marching technique samples the ray every
// `scale * |V.xy| / V.z / n` UV (n lerped from maxSamples to minSamples by V.z, reference 001).
// POM's linear intersection (reference 001) is exact where the field is linear between two
// samples, so on the smooth field its error is a small fraction of a layer (its curvature over
// one layer); where a vertical step hides between two samples it can be off by up to a layer.
// Relief mapping's binary search halves the bracket per refinement step, then interpolates.
// Measured on llvmpipe at 20 degrees (8/32 samples, layer 0.55 texel): POM 0.004 texel on the
// smooth field, 0.020 on the steps; relief (8/16, 5 steps) 0.001 and 0.017. The bounds below
// leave 5-8x headroom; the additive 0.01 texel covers GPUs that filter with 8-bit weights
// (1/256 texel).
#include "core/mesh/MeshPrimitives.h"
#include "core/tracing/ReliefTracer.h"
#include "core/tracing/UvErrorMap.h"
#include "support/OffscreenFixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace relief::test {
namespace {

using core::Image;
using core::ParamId;

constexpr int kFieldSize = 64;
constexpr double kScale = 0.08;

Image smoothField() {
  Image field(kFieldSize, kFieldSize, 1);
  const double k = 2.0 * std::numbers::pi / kFieldSize;
  for (int y = 0; y < kFieldSize; ++y) {
    for (int x = 0; x < kFieldSize; ++x) {
      field.at(x, y, 0) = float(0.5 + 0.45 * std::sin(2.0 * k * x) * std::sin(2.0 * k * y));
    }
  }
  return field;
}

Image steppedField() {
  // Square plateaus at 1.0 in a 0.2 floor: vertical walls one texel wide (bilinear).
  Image field(kFieldSize, kFieldSize, 1);
  for (int y = 0; y < kFieldSize; ++y) {
    for (int x = 0; x < kFieldSize; ++x) {
      field.at(x, y, 0) = ((x / 16 + y / 16) % 2 == 0) ? 1.0f : 0.2f;
    }
  }
  return field;
}

Image thinWallField() {
  // One-texel walls at 1.0 every 8 texels in a 0.1 floor: between two of POM's layers a wall
  // is easily stepped over at a grazing angle.
  Image field(kFieldSize, kFieldSize, 1);
  for (int y = 0; y < kFieldSize; ++y) {
    for (int x = 0; x < kFieldSize; ++x)
      field.at(x, y, 0) = (x % 8 == 0 || y % 8 == 0) ? 1.0f : 0.1f;
  }
  return field;
}

Image spikeField() {
  // Single-texel spikes at 1.0 every 16 texels on a floor at 0: the narrowest cones, and
  // features a layered march steps through.
  Image field(kFieldSize, kFieldSize, 1);
  for (int y = 0; y < kFieldSize; ++y) {
    for (int x = 0; x < kFieldSize; ++x)
      field.at(x, y, 0) = (x % 16 == 5 && y % 16 == 9) ? 1.0f : 0.0f;
  }
  return field;
}

struct Measurement {
  double meanErrorTexels = 0.0;
  double p95ErrorTexels = 0.0;
  double meanLayerTexels = 0.0;  // the layer spacing over the same pixels
  long long pixels = 0;
};

class ParallaxAccuracy : public OffscreenTest {
 protected:
  Measurement measure(const Image& field, core::Technique technique, int minSamples, int maxSamples,
                      float pitchDeg, int refinement = 5) {
    core::Material material;
    material.setMap(core::MapSlot::Height, std::make_shared<Image>(field));
    material.setTechnique(technique);
    material.setParameter(ParamId::HeightScale, kScale);
    material.setParameter(ParamId::HeightBias, -kScale);
    material.setParameter(ParamId::MinSamples, minSamples);
    material.setParameter(ParamId::MaxSamples, maxSamples);
    material.setParameter(ParamId::RefinementSteps, refinement);
    material.setParameter(ParamId::ShadowMode, double(core::ShadowMode::Off));
    return measureMaterial(material, field.width(), pitchDeg);
  }

  // The same for any material; `fieldWidth` is the height map's width in texels (the layer
  // spacing printed is in its texels).
  Measurement measureMaterial(const core::Material& material, int fieldWidth, float pitchDeg) {
    const core::Technique technique = material.technique();
    const int minSamples = int(material.parameter(ParamId::MinSamples));
    const int maxSamples = int(material.parameter(ParamId::MaxSamples));
    const double scale = material.parameter(ParamId::HeightScale);
    offscreen().setMaterial(material);
    offscreen().setMesh(core::makePlane());

    // Close enough that the 64-texel map is magnified everywhere: the GPU reads mip level 0,
    // the level the tracer uses (pixels where it does not are left out below).
    renderer::FrameSettings frame;
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.pitchDeg = pitchDeg;
    frame.view.camera.distance = 1.2f;
    const int size = 240;
    auto inputs = offscreen().renderErrorViewInputs(frame, size, size);
    EXPECT_TRUE(inputs.ok()) << inputs.error();
    frame.debugView = core::DebugView::Mip;
    frame.output = renderer::FrameOutput::FloatData;
    core::Result<Image> mip = offscreen().render(frame, size, size);
    EXPECT_TRUE(mip.ok());
    if (!inputs.ok() || !mip.ok())
      return {};

    const core::UvErrorMap errors =
        core::computeUvErrorMap(inputs->finalUv, inputs->eyeRays, inputs->field);
    Measurement result;
    std::vector<float> all;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const float error = errors.texels.at(x, y, 0);
        if (error < 0.0f || mip->at(x, y, 0) > 0.0f)
          continue;
        const float* ray = inputs->eyeRays.pixel(x, y);
        const double vxy = std::hypot(ray[2], ray[3]);
        const double vz = std::sqrt(std::max(1e-6, 1.0 - vxy * vxy));
        const int layers = std::max(int(maxSamples + (minSamples - maxSamples) * vz), 1);
        result.meanErrorTexels += error;
        all.push_back(error);
        result.meanLayerTexels += scale * vxy / vz / layers * fieldWidth;
        ++result.pixels;
      }
    }
    if (result.pixels > 0) {
      std::nth_element(all.begin(), all.begin() + std::ptrdiff_t(all.size() * 95 / 100), all.end());
      result.p95ErrorTexels = all[all.size() * 95 / 100];
      result.meanErrorTexels /= double(result.pixels);
      result.meanLayerTexels /= double(result.pixels);
    }
    // The numbers, for the record (ctest --verbose shows them).
    std::printf(
        "%-8s %2d/%-2d pitch %4.0f: mean error %.5f texels, p95 %.5f, layer %.4f texels, %lld px\n",
        std::string(core::techniqueName(technique)).c_str(), minSamples, maxSamples,
        double(pitchDeg), result.meanErrorTexels, result.p95ErrorTexels, result.meanLayerTexels,
        result.pixels);
    return result;
  }
};

TEST_F(ParallaxAccuracy, PomIsWithinAFractionOfALayerOnASmoothField) {
  for (float pitch : {85.0f, 20.0f}) {
    const Measurement m = measure(smoothField(), core::Technique::Pom, 8, 32, pitch);
    ASSERT_GT(m.pixels, 20000) << "too few pixels at mip level 0, pitch " << pitch;
    EXPECT_LT(m.meanErrorTexels, 0.05 * m.meanLayerTexels + 0.01)
        << "pitch " << pitch << ": layer " << m.meanLayerTexels << " texels";
  }
}

TEST_F(ParallaxAccuracy, PomStaysWithinALayerOnVerticalSteps) {
  for (float pitch : {85.0f, 20.0f}) {
    const Measurement m = measure(steppedField(), core::Technique::Pom, 8, 32, pitch);
    ASSERT_GT(m.pixels, 20000);
    EXPECT_LT(m.meanErrorTexels, 0.25 * m.meanLayerTexels + 0.01)
        << "pitch " << pitch << ": layer " << m.meanLayerTexels << " texels";
  }
}

TEST_F(ParallaxAccuracy, ErrorFallsAsSamplesGrow) {
  for (const Image& field : {smoothField(), steppedField()}) {
    double previous = 1e9;
    for (int samples : {8, 16, 32, 64}) {
      const Measurement m = measure(field, core::Technique::Pom, samples, samples, 20.0f);
      EXPECT_LT(m.meanErrorTexels, previous) << samples << " samples";
      previous = m.meanErrorTexels;
    }
  }
}

TEST_F(ParallaxAccuracy, ReliefRefinementBeatsPomAtEqualLinearSteps) {
  for (const Image& field : {smoothField(), steppedField()}) {
    for (float pitch : {85.0f, 20.0f}) {
      const Measurement pom = measure(field, core::Technique::Pom, 8, 16, pitch);
      const Measurement relief = measure(field, core::Technique::Relief, 8, 16, pitch, 5);
      EXPECT_LT(relief.meanErrorTexels, pom.meanErrorTexels) << "pitch " << pitch;
      EXPECT_LT(relief.meanErrorTexels, 0.05 * relief.meanLayerTexels + 0.01) << "pitch " << pitch;
    }
  }
}

TEST_F(ParallaxAccuracy, SteepParallaxIsWorseThanPom) {
  // Steep parallax stops at the first layer below the surface: up to a whole layer off.
  const Measurement steep = measure(smoothField(), core::Technique::Steep, 8, 32, 20.0f);
  const Measurement pom = measure(smoothField(), core::Technique::Pom, 8, 32, 20.0f);
  EXPECT_GT(steep.meanErrorTexels, 2.0 * pom.meanErrorTexels);
  EXPECT_LT(steep.meanErrorTexels, 1.0 * steep.meanLayerTexels + 0.01);
}

// The exact tracers reach the bilinear patch the reference tracer intersects: the quadtree
// walks the maximum-mipmap pyramid to the exact cell (Tevs et al. 2008), the cone technique
// cone-steps there (core/tracing/ConeMap.h) and both solve the patch's quadratic. What remains is
// float precision in the walk and the 8-bit filtering weights some GPUs use for the error view's
// UV pass. Measured on llvmpipe: see the printed lines.
constexpr core::Technique kExactTracers[] = {core::Technique::Quadtree, core::Technique::Cone};

TEST_F(ParallaxAccuracy, ExactTracersMeetTheExactTracerOnEveryField) {
  for (core::Technique technique : kExactTracers) {
    for (const Image& field : {smoothField(), steppedField(), thinWallField(), spikeField()}) {
      for (float pitch : {85.0f, 20.0f}) {
        const Measurement m = measure(field, technique, 8, 32, pitch);
        ASSERT_GT(m.pixels, 20000);
        EXPECT_LT(m.meanErrorTexels, 0.01) << core::techniqueName(technique) << " pitch " << pitch;
        EXPECT_LT(m.p95ErrorTexels, 0.02) << core::techniqueName(technique) << " pitch " << pitch;
      }
    }
  }
}

TEST_F(ParallaxAccuracy, ExactTracersKeepOneTexelWallsPomStepsOver) {
  const Measurement pom = measure(thinWallField(), core::Technique::Pom, 16, 16, 20.0f);
  EXPECT_GT(pom.p95ErrorTexels, 1.0);  // POM passes walls between its layers
  for (core::Technique technique : kExactTracers) {
    const Measurement exact = measure(thinWallField(), technique, 16, 16, 20.0f);
    EXPECT_LT(exact.p95ErrorTexels, 0.02) << core::techniqueName(technique);
    EXPECT_LT(exact.meanErrorTexels, 0.05 * pom.meanErrorTexels) << core::techniqueName(technique);
  }
}

// The paths a plain height map does not take: a non-square map whose sizes are not powers of
// two (odd pyramid levels, wrapping at both edges), depths (1 - h) packed in a normal map's
// alpha (the 16-bit normal texture), the middle of the relief on the surface, and tiling 2.
TEST_F(ParallaxAccuracy, ExactTracersAreExactForPackedDepthOnAnOddMap) {
  const int width = 40, height = 24;
  auto normals = std::make_shared<Image>(width, height, 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double h = (x % 10 == 0) ? 1.0 : 0.5 + 0.4 * std::sin(0.3 * x) * std::cos(0.5 * y);
      normals->at(x, y, 0) = 0.5f;
      normals->at(x, y, 1) = 0.5f;
      normals->at(x, y, 2) = 1.0f;
      normals->at(x, y, 3) = float(1.0 - h);  // a depth
    }
  }
  core::Material material;
  material.setMap(core::MapSlot::Normal, normals);
  material.setParameter(ParamId::HeightInNormalAlpha, 1.0);
  material.setParameter(ParamId::HeightIsDepth, 1.0);
  material.setParameter(ParamId::HeightScale, kScale);
  material.setParameter(ParamId::HeightBias, -kScale / 2);
  material.setParameter(ParamId::Tiling, 2.0);
  material.setParameter(ParamId::ShadowMode, double(core::ShadowMode::Off));
  for (core::Technique technique : kExactTracers) {
    material.setTechnique(technique);
    for (float pitch : {85.0f, 20.0f}) {
      const Measurement m = measureMaterial(material, width, pitch);
      ASSERT_GT(m.pixels, 20000) << "pitch " << pitch;
      // The 16-bit alpha is what both the GPU and the tracer read (the tracer from the float
      // image): a depth step of 1/65535 moves a grazing hit by about 0.001 texel.
      EXPECT_LT(m.meanErrorTexels, 0.01) << core::techniqueName(technique) << " pitch " << pitch;
      EXPECT_LT(m.p95ErrorTexels, 0.02) << core::techniqueName(technique) << " pitch " << pitch;
    }
  }
}

// Displacement tessellates the plane's two triangles into n segments per edge and moves the
// vertices to the height there: a piecewise-linear surface through samples of the bilinear
// field the tracer intersects, so its UV view converges to the tracer's as n grows. At n = 64
// on the 64-texel smooth field the segments are a texel long; linear interpolation of the
// field's sines (period 32 texels, amplitude 0.45) is then off by at most
// 0.45 (2 pi / 32)^2 / 8 = 0.0022 in h, 0.011 texel of height at scale 0.08, and the grazing
// view turns it into about 0.03 texel along the ray (measured on llvmpipe: 0.018 mean). That
// error shrinks with the segment length squared: doubling the segments from 32 to 64 should
// quarter it (measured: 0.070 -> 0.018 at 20 degrees, 0.010 -> 0.0026 head-on).
TEST_F(ParallaxAccuracy, DisplacementConvergesToTheExactTracerAsTessellationGrows) {
  core::Material material;
  material.setMap(core::MapSlot::Height, std::make_shared<Image>(smoothField()));
  material.setTechnique(core::Technique::Displacement);
  material.setParameter(ParamId::HeightScale, kScale);
  material.setParameter(ParamId::HeightBias, -kScale);
  material.setParameter(ParamId::ShadowMode, double(core::ShadowMode::Off));
  for (float pitch : {85.0f, 20.0f}) {
    double previous = 1e9;
    for (int segments : {2, 8, 32, 64}) {
      material.setParameter(ParamId::MaxTessellation, segments);
      std::printf("%d segments per edge: ", segments);
      const Measurement m = measureMaterial(material, kFieldSize, pitch);
      ASSERT_GT(m.pixels, 20000) << "pitch " << pitch;
      const double factor = segments == 64 ? 0.4 : 0.7;  // 32 -> 64: about a quarter
      EXPECT_LT(m.meanErrorTexels, factor * previous) << segments << " segments, pitch " << pitch;
      previous = m.meanErrorTexels;
    }
    EXPECT_LT(previous, 0.06) << "pitch " << pitch;
  }
}

// The error view traces the full-resolution map. Seen from afar the GPU reads coarser mip
// levels, where every technique sees a filtered map and would read as wrong (issue: a plane at
// 10 degrees read 3.6 texels of mean error for the exact quadtree); those pixels are left out of
// the statistics and counted apart, so at the same view the exact tracer reads near zero and
// POM's error still falls with its samples. A 256-texel map of 32-texel plateaus at 10 degrees:
// the near rows are magnified, the far ones minified.
TEST_F(ParallaxAccuracy, ErrorViewLeavesOutPixelsWhereTheMapIsMinified) {
  constexpr int kPlateauSize = 256;
  Image field(kPlateauSize, kPlateauSize, 1);
  for (int y = 0; y < kPlateauSize; ++y) {
    for (int x = 0; x < kPlateauSize; ++x)
      field.at(x, y, 0) = ((x / 32 + y / 32) % 2 == 0) ? 0.9f : 0.2f;
  }
  const auto errorView = [&](core::Technique technique, int samples) {
    core::Material material;
    material.setMap(core::MapSlot::Height, std::make_shared<Image>(field));
    material.setTechnique(technique);
    material.setParameter(ParamId::HeightScale, kScale);
    material.setParameter(ParamId::HeightBias, -kScale);
    material.setParameter(ParamId::SamplesPerTexel, 0);  // reference 001's angle rule
    material.setParameter(ParamId::MinSamples, samples);
    material.setParameter(ParamId::MaxSamples, samples);
    material.setParameter(ParamId::ShadowMode, double(core::ShadowMode::Off));
    offscreen().setMaterial(material);
    offscreen().setMesh(core::makePlane());
    renderer::FrameSettings frame;
    frame.view.camera.pitchDeg = 10.0f;
    frame.view.camera.distance = 1.2f;
    auto inputs = offscreen().renderErrorViewInputs(frame, 320, 240);
    EXPECT_TRUE(inputs.ok()) << inputs.error();
    if (!inputs.ok())
      return core::UvErrorMap{};
    core::UvErrorMap map = core::computeUvErrorMap(inputs->finalUv, inputs->eyeRays, inputs->field);
    std::printf("%-8s %3d samples at 10 degrees: %s\n",
                std::string(core::techniqueName(technique)).c_str(), samples,
                core::describeUvError(map).c_str());
    return map;
  };
  const core::UvErrorMap quadtree = errorView(core::Technique::Quadtree, 8);
  ASSERT_GT(quadtree.pixels, 5000);
  EXPECT_GT(quadtree.minifiedPixels, quadtree.pixels / 5) << "the view should reach mip level 1";
  EXPECT_LT(quadtree.mean, 0.02);
  EXPECT_LT(quadtree.p95, 0.05);
  const core::UvErrorMap coarse = errorView(core::Technique::Pom, 8);
  const core::UvErrorMap fine = errorView(core::Technique::Pom, 128);
  EXPECT_GT(coarse.mean, 2.0 * fine.mean);
  EXPECT_GT(coarse.mean, 10.0 * quadtree.mean);
  // The summary says what was left out, as the CLI and the viewport print it.
  EXPECT_NE(core::describeUvError(quadtree).find("minified (mip level 1 or more) left out"),
            std::string::npos);
}

}  // namespace
}  // namespace relief::test
