// Blinn-Phong normal mapping (reference 004) against values computed by hand: a constant
// normal map tilted along +X or +Y, lit from known directions, must give exactly
// albedo * dot(N, L) per pixel. This pins down the tangent frame's orientation (the normal
// map's X and Y point the right way, with the OpenGL Y+ convention), the sRGB decode of the
// colour map and the sRGB encode of the output.
#include "core/image/ColorSpace.h"
#include "core/mesh/MeshPrimitives.h"
#include "support/OffscreenFixture.h"

#include <cmath>

namespace relief::test {
namespace {

using core::Image;
using core::MapSlot;
using core::ParamId;

std::shared_ptr<Image> constantImage(int channels, std::initializer_list<float> values) {
  auto image = std::make_shared<Image>(8, 8, channels);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      int c = 0;
      for (float value : values)
        image->at(x, y, c++) = value;
    }
  }
  return image;
}

class Lighting : public OffscreenTest {
 protected:
  // Renders a plane seen from straight above with a constant tangent-space normal, a constant
  // sRGB albedo and the light at the given azimuth/elevation; returns the centre pixel's red.
  float centreRed(glm::vec3 tangentNormal, float albedoSrgb, float lightAzimuth,
                  float lightElevation, bool yDown = false) {
    core::Material material;
    const glm::vec3 encoded = glm::normalize(tangentNormal) * 0.5f + 0.5f;
    material.setMap(MapSlot::Normal, constantImage(3, {encoded.x, encoded.y, encoded.z}));
    material.setMap(MapSlot::Color, constantImage(3, {albedoSrgb, albedoSrgb, albedoSrgb}));
    // Classic shading: Lambert under the light plus the flat ambient, the formula the tests
    // below expect (PbrShadingTest covers pbr's).
    material.setParameter(ParamId::Shading, double(core::ShadingModel::Classic));
    material.setParameter(ParamId::Specular, 0.0);
    material.setParameter(ParamId::NormalYDown, yDown ? 1.0 : 0.0);
    offscreen().setMaterial(material);
    offscreen().setMesh(core::makePlane());

    renderer::RenderView view;
    view.camera.yawDeg = 0.0f;
    view.camera.pitchDeg = 89.0f;
    view.camera.distance = 2.0f;
    view.light.azimuthDeg = lightAzimuth;
    view.light.elevationDeg = lightElevation;
    view.light.color = glm::vec3(1.0f);
    view.light.intensity = 1.0f;
    view.light.ambient = 0.0f;
    core::Result<Image> image = offscreen().render(view, 33, 33);
    EXPECT_TRUE(image.ok()) << image.error();
    return image.ok() ? image->at(16, 16, 0) : -1.0f;
  }

  static float expectedRed(float albedoSrgb, float nDotL) {
    return core::linearToSrgb(core::srgbToLinear(albedoSrgb) * std::max(nDotL, 0.0f));
  }
};

// Output is 8-bit: allow the rounding of the colour texture, the normal texture and the output.
constexpr float kTolerance = 1.5f / 255.0f;

TEST_F(Lighting, NormalTiltedTowardPlusXFacesALightFromPlusX) {
  // Plane: T = +X (world), B = -Z, N = +Y. Light azimuth 90 = toward +X, elevation 45:
  // L_tangent = (cos45, 0, sin45).
  const glm::vec3 n = glm::normalize(glm::vec3(0.6f, 0.0f, 0.8f));
  const float s = std::sqrt(0.5f);
  EXPECT_NEAR(centreRed(n, 1.0f, 90.0f, 45.0f), expectedRed(1.0f, n.x * s + n.z * s), kTolerance);
  EXPECT_NEAR(centreRed(n, 1.0f, 270.0f, 45.0f), expectedRed(1.0f, -n.x * s + n.z * s), kTolerance);
}

TEST_F(Lighting, NormalTiltedTowardPlusYFacesALightFromUpTheTexture) {
  // +v runs toward -Z on the plane, so a light from azimuth 180 (toward -Z) lies along +Y in
  // tangent space.
  const glm::vec3 n = glm::normalize(glm::vec3(0.0f, 0.6f, 0.8f));
  const float s = std::sqrt(0.5f);
  const float facing = n.y * s + n.z * s;
  const float away = -n.y * s + n.z * s;
  EXPECT_NEAR(centreRed(n, 1.0f, 180.0f, 45.0f), expectedRed(1.0f, facing), kTolerance);
  EXPECT_NEAR(centreRed(n, 1.0f, 0.0f, 45.0f), expectedRed(1.0f, away), kTolerance);
  // A DirectX normal map stores -Y: the same texels read with normalYDown face the other way.
  EXPECT_NEAR(centreRed(n, 1.0f, 180.0f, 45.0f, true), expectedRed(1.0f, away), kTolerance);
}

TEST_F(Lighting, ColourMapIsDecodedFromSrgbAndOutputEncodedToSrgb) {
  // Head-on light on a flat normal: output = encode(decode(albedo)) = albedo.
  for (float albedo : {0.2f, 0.5f, 0.8f}) {
    const float quantized = std::round(albedo * 255.0f) / 255.0f;
    EXPECT_NEAR(centreRed({0, 0, 1}, quantized, 0.0f, 90.0f), quantized, kTolerance);
  }
  // Half the light: linear halving, not sRGB halving (0.5 in sRGB would be 0.25 linear).
  const float s30 = std::sin(30.0f * 3.14159265f / 180.0f);
  EXPECT_NEAR(centreRed({0, 0, 1}, 1.0f, 0.0f, 30.0f), core::linearToSrgb(s30), kTolerance);
}

}  // namespace
}  // namespace relief::test
