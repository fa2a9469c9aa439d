// Metallic-roughness shading (shading = pbr) in the shader, against the glTF BRDF's C++
// reference (core/shading/Brdf.h) and quadrature of it (support/BrdfQuadrature), on the linear
// radiance the float output writes:
// - the white furnace: a white dielectric of roughness 1 and white metals under a uniform
//   environment of radiance 1 reflect 1 everywhere on a sphere (energy is conserved: the split
//   sum plus multiple scattering);
// - a black dielectric reflects the specular lobe's directional albedo (checks the table's
//   axes and its sampling);
// - the directional light reflects f(l, v) (N.L) pi E at a known pixel.
#include "core/image/ColorSpace.h"
#include "core/mesh/MeshPrimitives.h"
#include "core/shading/Brdf.h"
#include "core/view/DisplayTransform.h"
#include "support/BrdfQuadrature.h"
#include "support/OffscreenFixture.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace relief::test {
namespace {

using core::Image;
using core::MapSlot;
using core::ParamId;

std::shared_ptr<Image> constantColor(float srgb) {
  auto image = std::make_shared<Image>(4, 4, 3, core::ColorSpace::Srgb);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      for (int c = 0; c < 3; ++c)
        image->at(x, y, c) = srgb;
  return image;
}

core::Material pbrMaterial(float colorSrgb, float metallic, float roughness) {
  core::Material material;
  material.setTechnique(core::Technique::Normal);
  material.setParameter(ParamId::Shading, double(int(core::ShadingModel::Pbr)));
  material.setParameter(ParamId::Metallic, metallic);
  material.setParameter(ParamId::Roughness, roughness);
  material.setParameter(ParamId::ShadowMode, double(int(core::ShadowMode::Off)));
  material.setMap(MapSlot::Color, constantColor(colorSrgb));
  return material;
}

class PbrShading : public OffscreenTest {
 protected:
  // The linear radiance of the sphere under a uniform environment of radiance 1, no light.
  Image furnace(const core::Material& material) {
    offscreen().setMesh(core::makeSphere());
    offscreen().setMaterial(material);
    renderer::FrameSettings frame;
    frame.output = renderer::FrameOutput::FloatData;
    frame.view.camera.frame(core::makeSphere().bounds(), 1.0f);
    frame.view.light.intensity = 0.0f;
    frame.view.environment.source = "uniform";
    frame.view.environment.intensity = 1.0f;
    core::Result<Image> image = offscreen().render(frame, 96, 96);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? std::move(image).value() : Image(1, 1, 4);
  }

  // Over the pixels the sphere covers (alpha 1): the largest |radiance - 1| of any channel.
  static double worstFurnaceError(const Image& image, int& covered) {
    double worst = 0.0;
    covered = 0;
    for (int y = 0; y < image.height(); ++y) {
      for (int x = 0; x < image.width(); ++x) {
        if (image.at(x, y, 3) < 1.0f)
          continue;
        ++covered;
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, std::abs(double(image.at(x, y, c)) - 1.0));
      }
    }
    return worst;
  }
};

// The bounds are 5% (dielectric) and 3% (metal); the split sum with multiple
// scattering conserves energy exactly, so what remains is the table's interpolation and float
// rounding: 1%.
TEST_F(PbrShading, TheWhiteFurnaceReflectsTheEnvironmentExactly) {
  struct Case {
    float metallic, roughness;
  };
  for (Case c : {Case{0.0f, 1.0f}, Case{1.0f, 0.0f}, Case{1.0f, 0.5f}, Case{0.0f, 0.3f}}) {
    int covered = 0;
    const double worst =
        worstFurnaceError(furnace(pbrMaterial(1.0f, c.metallic, c.roughness)), covered);
    EXPECT_GT(covered, 96 * 96 / 3);
    EXPECT_LT(worst, 0.01) << "metallic " << c.metallic << " roughness " << c.roughness;
  }
}

// A black dielectric keeps only the specular layer: at the sphere's centre (N.V = 1) it
// reflects the lobe's directional albedo, which quadrature of the BRDF gives; the shader's
// multiple-scattering term adds under 0.1% at f0 = 0.04.
TEST_F(PbrShading, ABlackDielectricReflectsTheSpecularAlbedo) {
  for (float roughness : {0.4f, 0.8f}) {
    const Image image = furnace(pbrMaterial(0.0f, 0.0f, roughness));
    const float centre = image.at(48, 48, 0);
    const float expected = directionalAlbedo(glm::vec3(0.0f), 0.0f, roughness, 0.999f, 512).x;
    EXPECT_NEAR(centre, expected, 0.03f * expected + 0.001f) << roughness;
  }
  // Rougher is not brighter at normal incidence here, but the two must differ: the table is
  // read along its roughness axis.
  const float smooth = furnace(pbrMaterial(0.0f, 0.0f, 0.4f)).at(48, 48, 0);
  const float rough = furnace(pbrMaterial(0.0f, 0.0f, 0.8f)).at(48, 48, 0);
  EXPECT_GT(std::abs(smooth - rough), 0.002f);
}

// A plane seen from straight above, lit at 40 degrees, with no environment light: the centre
// pixel reflects f(l, v) (N.L) pi E (pbr.glsl's light convention), with f from core::gltfBrdf.
struct LitPlane {
  renderer::FrameSettings frame;
  glm::vec3 l, v;  // in the plane's tangent space

  LitPlane() {
    frame.output = renderer::FrameOutput::FloatData;
    frame.view.camera.yawDeg = 0.0f;
    frame.view.camera.pitchDeg = 89.0f;
    frame.view.camera.distance = 2.0f;
    frame.view.light.azimuthDeg = 90.0f;
    frame.view.light.elevationDeg = 40.0f;
    frame.view.light.color = glm::vec3(1.0f);
    frame.view.light.intensity = 1.5f;
    frame.view.environment.intensity = 0.0f;
    // World to the plane's tangent space: T = +X, B = -Z, N = +Y.
    const auto tangent = [](glm::vec3 w) { return glm::normalize(glm::vec3(w.x, -w.z, w.y)); };
    l = tangent(frame.view.light.direction());
    v = tangent(frame.view.camera.position() - frame.view.camera.target);
  }

  // What the centre pixel shows for a base colour of sRGB 0.8.
  float expected(float metallic, float roughness) const {
    const float base = core::srgbToLinear(0.8f);
    return core::gltfBrdf(glm::vec3(base), metallic, roughness, glm::vec3(0.0f, 0.0f, 1.0f), l, v)
               .x *
           l.z * core::kPi * frame.view.light.intensity;
  }
};

TEST_F(PbrShading, TheDirectionalLightReflectsTheBrdf) {
  offscreen().setMesh(core::makePlane());
  const LitPlane plane;
  for (float metallic : {0.0f, 1.0f}) {
    for (float roughness : {0.3f, 0.7f}) {
      offscreen().setMaterial(pbrMaterial(0.8f, metallic, roughness));
      core::Result<Image> image = offscreen().render(plane.frame, 33, 33);
      ASSERT_TRUE(image.ok()) << image.error();
      const float expected = plane.expected(metallic, roughness);
      EXPECT_NEAR(image->at(16, 16, 0), expected, 0.02f * expected)
          << "metallic " << metallic << " roughness " << roughness;
    }
  }
}

// The metallic map multiplies the metallic factor (glTF's metallicRoughnessTexture blue): with
// a map of constant m and factor f the lit plane reflects the BRDF of metallic f m, so a map
// of 0 is a dielectric whatever the factor.
TEST_F(PbrShading, TheMetallicMapMultipliesTheMetallicFactor) {
  offscreen().setMesh(core::makePlane());
  const LitPlane plane;
  struct Case {
    float factor, map;
  };
  for (Case c : {Case{1.0f, 0.5f}, Case{0.6f, 1.0f}, Case{0.6f, 0.0f}}) {
    core::Material material = pbrMaterial(0.8f, c.factor, 0.4f);
    auto map = std::make_shared<Image>(4, 4, 1);
    std::fill(map->data(), map->data() + map->valueCount(), c.map);
    material.setMap(MapSlot::Metallic, map);
    offscreen().setMaterial(material);
    core::Result<Image> image = offscreen().render(plane.frame, 33, 33);
    ASSERT_TRUE(image.ok()) << image.error();
    const float expected = plane.expected(c.factor * c.map, 0.4f);
    EXPECT_NEAR(image->at(16, 16, 0), expected, 0.02f * expected)
        << "factor " << c.factor << " map " << c.map;
  }
}

// The display output is the float output's radiance through the display transform (exposure,
// then Khronos PBR Neutral or ACES filmic) and the sRGB encoding, computed here by
// core::applyDisplayTransform; 1.5/255 allows the output's 8-bit rounding. A bright light puts
// much of the sphere above 1.
TEST_F(PbrShading, TheDisplayShowsTheRadianceThroughTheDisplayTransform) {
  offscreen().setMesh(core::makeSphere());
  offscreen().setMaterial(pbrMaterial(0.9f, 0.0f, 0.4f));
  for (core::ToneMapper mapper : {core::ToneMapper::PbrNeutral, core::ToneMapper::Aces}) {
    renderer::FrameSettings frame;
    frame.view.camera.frame(core::makeSphere().bounds(), 1.0f);
    frame.view.light.intensity = 3.0f;
    frame.view.display = core::DisplayTransform{0.5f, mapper};
    frame.output = renderer::FrameOutput::FloatData;
    core::Result<Image> radiance = offscreen().render(frame, 64, 64);
    frame.output = renderer::FrameOutput::Display;
    core::Result<Image> shown = offscreen().render(frame, 64, 64);
    ASSERT_TRUE(radiance.ok() && shown.ok());
    double worst = 0.0;
    int aboveOne = 0;
    for (int y = 0; y < 64; ++y) {
      for (int x = 0; x < 64; ++x) {
        if (radiance->at(x, y, 3) < 1.0f)
          continue;
        const glm::vec3 linear(radiance->at(x, y, 0), radiance->at(x, y, 1), radiance->at(x, y, 2));
        aboveOne += linear.r * frame.view.display.exposureScale() > 1.0f;
        const glm::vec3 expected = core::applyDisplayTransform(frame.view.display, linear);
        for (int c = 0; c < 3; ++c) {
          const double encoded = core::linearToSrgb(std::clamp(expected[c], 0.0f, 1.0f));
          worst = std::max(worst, std::abs(encoded - double(shown->at(x, y, c))));
        }
      }
    }
    EXPECT_GT(aboveOne, 50) << core::toneMapperName(mapper);
    EXPECT_LT(worst, 1.5 / 255.0) << core::toneMapperName(mapper);
  }
}

}  // namespace
}  // namespace relief::test
