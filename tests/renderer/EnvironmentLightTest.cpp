// Image-based light (renderer/EnvironmentLight, shaders/environment_prefilter.frag) and the
// environment background, on the GPU, against integrals computed here on the CPU:
// - a single bright texel, prefiltered, spreads as the GGX lobe predicts: the split-sum
//   prefilter's integral P(n) = sum L (n.l) D(h) / sum (n.l) D(h) over the source's texels
//   (N = V = R, Karis 2013), and the irradiance is L omega (n.d) / pi;
// - the environment is oriented as core/shading/EnvironmentMaps.h lays it out, in the
//   material's lighting and in the background alike, and rotation turns both;
// - a uniform environment prefilters to itself (the white furnace's premise).
#include "core/image/ImageIO.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/shading/Brdf.h"
#include "core/shading/EnvironmentMaps.h"
#include "renderer/EnvironmentLight.h"
#include "renderer/OffscreenRenderer.h"
#include "support/OffscreenFixture.h"
#include "support/TestPaths.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace relief::test {
namespace {

using core::Image;
using core::ParamId;

constexpr double kPi = 3.14159265358979;

// Solid angle of texel row y of a W x H equirect.
double texelSolidAngle(int y, int width, int height) {
  const double theta0 = double(y) / height * kPi, theta1 = double(y + 1) / height * kPi;
  return (std::cos(theta0) - std::cos(theta1)) * 2.0 * kPi / width;
}

glm::vec3 texelDirection(int x, int y, int width, int height) {
  return core::equirectDirection(
      glm::vec2((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)));
}

// An environment that is black but for one texel, written as an EXR (so the file path, the
// loader and the upload are part of the test).
struct BrightTexel {
  int width = 128, height = 64, x = 80, y = 26;
  float radiance = 2000.0f;
  std::string write() const {
    Image image(width, height, 3);
    for (int c = 0; c < 3; ++c)
      image.at(x, y, c) = radiance;
    const std::string path = scratchFolder() + "/bright_texel.exr";
    EXPECT_TRUE(core::saveImage(image, path, core::SampleFormat::Float).ok());
    return path;
  }
  glm::vec3 direction() const { return texelDirection(x, y, width, height); }
  double solidAngle() const { return texelSolidAngle(y, width, height); }
};

// The prefilter's weight of a light direction l for the output direction n (N = V = R):
// (n.l) D(h) / 4, h the half vector, as a density over directions.
double lobeWeight(const glm::vec3& n, const glm::vec3& l, float roughness) {
  const float nDotL = glm::dot(n, l);
  if (nDotL <= 0.0f)
    return 0.0;
  const glm::vec3 h = glm::normalize(n + l);
  const float alpha = roughness * roughness;
  return double(nDotL) * core::ggxDistribution(alpha, glm::dot(n, h)) / 4.0;
}

// The normalisation: the integral of lobeWeight over the sphere (the same for every n),
// by the midpoint rule on a fine equirect about n = +Y.
double lobeNormalisation(float roughness) {
  const int width = 2048, height = 1024;
  double sum = 0.0;
  for (int y = 0; y < height / 2; ++y) {
    const double omega = texelSolidAngle(y, width, height);
    const glm::vec3 l = texelDirection(0, y, width, height);
    sum += lobeWeight(glm::vec3(0, 1, 0),
                      glm::normalize(glm::vec3(std::sqrt(1 - l.y * l.y), l.y, 0)), roughness) *
           omega * width;
  }
  return sum;
}

class Prefiltering : public OffscreenTest {};

// Level 3 (roughness 0.5) and level 6 (roughness 1). Over the texels where the reference is
// above 2% of its peak, the GPU's prefilter is compared texel by texel, and its total (the
// light the level carries, summed over solid angle) must match. Filtered importance sampling
// reads coarser source levels for samples of low density, which blurs the single texel a little
// beyond the lobe: the bounds (15% of the peak per texel, 6% of the total) allow that, and a
// lobe of the wrong width (alpha = roughness instead of its square, or the pdf without the 1/4)
// is far outside them.
TEST_F(Prefiltering, ASingleBrightTexelSpreadsAsTheGgxLobePredicts) {
  const BrightTexel bright;
  core::Result<renderer::PrefilteredEnvironment> prefiltered =
      offscreen().prefilterEnvironment(bright.write());
  ASSERT_TRUE(prefiltered.ok()) << prefiltered.error();
  for (int level : {3, 6}) {
    const float roughness = float(level) / float(renderer::EnvironmentLight::kSpecularLevels - 1);
    const Image& gpu = prefiltered->specular[std::size_t(level)];
    const double normalisation = lobeNormalisation(roughness);
    double peak = 0.0, worst = 0.0, gpuTotal = 0.0, cpuTotal = 0.0;
    std::vector<double> expected(std::size_t(gpu.width() * gpu.height()));
    for (int y = 0; y < gpu.height(); ++y) {
      for (int x = 0; x < gpu.width(); ++x) {
        const glm::vec3 n = texelDirection(x, y, gpu.width(), gpu.height());
        const double value = bright.radiance * bright.solidAngle() *
                             lobeWeight(n, bright.direction(), roughness) / normalisation;
        expected[std::size_t(y * gpu.width() + x)] = value;
        peak = std::max(peak, value);
        const double omega = texelSolidAngle(y, gpu.width(), gpu.height());
        cpuTotal += value * omega;
        gpuTotal += double(gpu.at(x, y, 0)) * omega;
      }
    }
    for (int y = 0; y < gpu.height(); ++y) {
      for (int x = 0; x < gpu.width(); ++x) {
        const double value = expected[std::size_t(y * gpu.width() + x)];
        if (value > 0.02 * peak)
          worst = std::max(worst, std::abs(double(gpu.at(x, y, 0)) - value) / peak);
      }
    }
    EXPECT_LT(worst, 0.15) << "level " << level;
    EXPECT_NEAR(gpuTotal / cpuTotal, 1.0, 0.06) << "level " << level;
  }
}

// The irradiance over pi of a small source: L omega (n.d) / pi. Compared where n faces it by
// more than 0.2 (near the terminator the source's blur, a few degrees wide, dominates), and the
// side facing away must be dark.
TEST_F(Prefiltering, TheIrradianceOfASingleTexelFollowsTheCosine) {
  const BrightTexel bright;
  core::Result<renderer::PrefilteredEnvironment> prefiltered =
      offscreen().prefilterEnvironment(bright.write());
  ASSERT_TRUE(prefiltered.ok()) << prefiltered.error();
  const Image& irradiance = prefiltered->irradiance;
  const double scale = bright.radiance * bright.solidAngle() / kPi;
  double worst = 0.0, darkest = 0.0;
  for (int y = 0; y < irradiance.height(); ++y) {
    for (int x = 0; x < irradiance.width(); ++x) {
      const glm::vec3 n = texelDirection(x, y, irradiance.width(), irradiance.height());
      const double cosine = glm::dot(n, bright.direction());
      const double value = irradiance.at(x, y, 1);
      if (cosine > 0.2)
        worst = std::max(worst, std::abs(value - scale * cosine) / scale);
      if (cosine < -0.2)
        darkest = std::max(darkest, value / scale);
    }
  }
  EXPECT_LT(worst, 0.08);
  EXPECT_LT(darkest, 0.01);
}

TEST_F(Prefiltering, AUniformEnvironmentPrefiltersToItself) {
  core::Result<renderer::PrefilteredEnvironment> prefiltered =
      offscreen().prefilterEnvironment("uniform");
  ASSERT_TRUE(prefiltered.ok()) << prefiltered.error();
  for (const Image& level : prefiltered->specular) {
    for (int y = 0; y < level.height(); ++y)
      for (int x = 0; x < level.width(); ++x)
        ASSERT_NEAR(level.at(x, y, 0), 1.0f, 2e-3f) << level.width() << " " << x << "," << y;
  }
  for (int y = 0; y < prefiltered->irradiance.height(); ++y)
    for (int x = 0; x < prefiltered->irradiance.width(); ++x)
      ASSERT_NEAR(prefiltered->irradiance.at(x, y, 2), 1.0f, 2e-3f);
}

// An environment red toward -X and green toward +X (the map's left and right halves). The
// camera looks along -Z from +Z, so -X is the left of the picture: the background is red on
// the left, and a rough white sphere lit by the environment alone is red on its left and green
// on its right. Rotated by 180 degrees, both swap.
class EnvironmentOrientation : public OffscreenTest {
 protected:
  static std::string halves() {
    Image image(64, 32, 3);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 64; ++x)
        image.at(x, y, x < 32 ? 0 : 1) = 0.5f;
    const std::string path = scratchFolder() + "/halves.exr";
    EXPECT_TRUE(core::saveImage(image, path, core::SampleFormat::Half).ok());
    return path;
  }

  Image render(float rotationDeg, renderer::FrameOutput output) {
    core::Material material;
    material.setTechnique(core::Technique::Normal);
    material.setParameter(ParamId::Shading, double(int(core::ShadingModel::Pbr)));
    material.setParameter(ParamId::Roughness, 1.0);
    material.setParameter(ParamId::ShadowMode, double(int(core::ShadowMode::Off)));
    offscreen().setMesh(core::makeSphere());
    offscreen().setMaterial(material);
    renderer::FrameSettings frame;
    frame.output = output;
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.pitchDeg = 0.0f;
    frame.view.camera.frame(core::makeSphere().bounds(), 2.0f);
    EXPECT_GT(frame.view.camera.position().z, 0.0f);
    frame.view.light.intensity = 0.0f;
    frame.view.environment.source = s_halves;
    frame.view.environment.rotationDeg = rotationDeg;
    frame.view.environment.background = core::Background::Environment;
    core::Result<Image> image = offscreen().render(frame, 128, 64);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : Image(128, 64, 4);
  }

  static void SetUpTestSuite() {
    OffscreenTest::SetUpTestSuite();
    s_halves = halves();
  }
  static inline std::string s_halves;
};

TEST_F(EnvironmentOrientation, TheBackgroundAndTheLightComeFromTheSameSide) {
  for (float rotation : {0.0f, 180.0f}) {
    const bool swapped = rotation != 0.0f;
    const int leftChannel = swapped ? 1 : 0, rightChannel = swapped ? 0 : 1;
    const Image shown = render(rotation, renderer::FrameOutput::Display);
    // The background, at the picture's edges (the sphere spans the middle half).
    EXPECT_GT(shown.at(4, 32, leftChannel), 0.5f) << rotation;
    EXPECT_LT(shown.at(4, 32, rightChannel), 0.05f) << rotation;
    EXPECT_GT(shown.at(123, 32, rightChannel), 0.5f) << rotation;
    EXPECT_LT(shown.at(123, 32, leftChannel), 0.05f) << rotation;
    // The sphere's radiance a tenth of its width in from its left and right limbs, where the
    // normal's x is about -0.8 and +0.8: (1 + 0.8) / 2 of its cosine-weighted light comes from
    // the half it leans to, 9 times what the other half gives.
    const Image radiance = render(rotation, renderer::FrameOutput::FloatData);
    int first = -1, last = -1;
    for (int x = 0; x < radiance.width(); ++x) {
      if (radiance.at(x, 32, 3) == 1.0f) {
        first = first < 0 ? x : first;
        last = x;
      }
    }
    ASSERT_GT(last - first, 20);
    const int inset = (last - first) / 10;
    const float* left = radiance.pixel(first + inset, 32);
    const float* right = radiance.pixel(last - inset, 32);
    EXPECT_GT(left[leftChannel], 3.0f * left[rightChannel]) << rotation;
    EXPECT_GT(right[rightChannel], 3.0f * right[leftChannel]) << rotation;
  }
  // The sign: at +90 degrees the map's -X half (red) turns to face -Z, straight ahead, seen
  // above the sphere at the top of the picture; at -90 the +X half (green) does.
  const Image turnedLeft = render(90.0f, renderer::FrameOutput::Display);
  EXPECT_GT(turnedLeft.at(64, 2, 0), 0.5f);
  EXPECT_LT(turnedLeft.at(64, 2, 1), 0.05f);
  const Image turnedRight = render(-90.0f, renderer::FrameOutput::Display);
  EXPECT_GT(turnedRight.at(64, 2, 1), 0.5f);
  EXPECT_LT(turnedRight.at(64, 2, 0), 0.05f);
}

}  // namespace
}  // namespace relief::test
