// The split-sum table (Karis 2013) of the glTF BRDF against plain quadrature of the BRDF
// itself (support/BrdfQuadrature): f0 * A + B is the directional albedo of the specular lobe,
// so a white metal (f0 = 1, no diffuse) reflects A + B and a black metal (f0 = 0) reflects B.
// The quadrature runs through core::gltfBrdf, the table through the importance-sampled
// integral: two computations that agree only if both are right.
#include "core/shading/Brdf.h"
#include "core/shading/SplitSumLut.h"
#include "support/BrdfQuadrature.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

namespace relief::test {
namespace {

// 4096 Hammersley samples against a 512 x 1024 midpoint rule. The quadrature has converged to
// 1e-5 at these roughnesses (doubling its steps changes nothing); the sampled integral is within
// 0.3% at 4096 samples even at N.V = 0.15, where samples past the horizon are lost (1.2% at
// 1024, which is why the renderer's table takes 4096).
constexpr float kTolerance = 0.006f;

TEST(SplitSumLut, MatchesQuadratureOfTheBrdfOverNDotVAndRoughness) {
  for (float nDotV : {0.15f, 0.5f, 0.95f}) {
    for (float roughness : {0.35f, 0.6f, 1.0f}) {
      const core::SplitSumTerms terms = core::integrateSplitSum(nDotV, roughness, 4096);
      const float white = directionalAlbedo(glm::vec3(1.0f), 1.0f, roughness, nDotV, 512).x;
      const float black = directionalAlbedo(glm::vec3(0.0f), 1.0f, roughness, nDotV, 512).x;
      EXPECT_NEAR(terms.scale + terms.bias, white, kTolerance) << nDotV << " " << roughness;
      EXPECT_NEAR(terms.bias, black, kTolerance) << nDotV << " " << roughness;
    }
  }
}

// A mirror reflects everything (A + B = 1 at f0 = 1); rough surfaces lose energy to single
// scattering, more at grazing views (the loss multiple scattering gives back in the shader).
TEST(SplitSumLut, AMirrorKeepsAllTheEnergyAndRoughnessLosesSome) {
  for (float nDotV : {0.1f, 0.5f, 1.0f}) {
    const core::SplitSumTerms mirror = core::integrateSplitSum(nDotV, 0.02f, 256);
    EXPECT_NEAR(mirror.scale + mirror.bias, 1.0f, 0.005f) << nDotV;
  }
  const auto energy = [](float roughness) {
    const core::SplitSumTerms terms = core::integrateSplitSum(0.5f, roughness, 4096);
    return terms.scale + terms.bias;
  };
  EXPECT_GT(energy(0.3f), energy(0.6f));
  EXPECT_GT(energy(0.6f), energy(1.0f));
  EXPECT_LT(energy(1.0f), 0.6f);  // GGX at alpha 1 keeps about half in one bounce
}

TEST(SplitSumLut, TheTableHoldsTheIntegralAtTexelCentres) {
  const core::Image table = core::makeSplitSumLut(8, 256);
  ASSERT_EQ(table.width(), 8);
  for (auto [column, row] : {std::pair{0, 0}, std::pair{7, 2}, std::pair{3, 7}}) {
    const core::SplitSumTerms terms =
        core::integrateSplitSum((float(column) + 0.5f) / 8.0f, (float(row) + 0.5f) / 8.0f, 256);
    EXPECT_EQ(table.at(column, row, 0), terms.scale);
    EXPECT_EQ(table.at(column, row, 1), terms.bias);
  }
}

// The BRDF itself: reciprocal, and a white Lambert dielectric at roughness 1 reflects close to
// all of a uniform environment (the little the Fresnel layer takes it partly gives back).
TEST(GltfBrdf, IsReciprocalAndAWhiteDielectricReflectsAboutEverything) {
  const glm::vec3 n(0.0f, 0.0f, 1.0f);
  const glm::vec3 l = glm::normalize(glm::vec3(0.3f, -0.2f, 0.8f));
  const glm::vec3 v = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.6f));
  const glm::vec3 base(0.8f, 0.5f, 0.2f);
  for (float metallic : {0.0f, 0.4f, 1.0f}) {
    const glm::vec3 forward = core::gltfBrdf(base, metallic, 0.45f, n, l, v);
    const glm::vec3 backward = core::gltfBrdf(base, metallic, 0.45f, n, v, l);
    EXPECT_NEAR(forward.x, backward.x, 1e-5f);
    EXPECT_NEAR(forward.z, backward.z, 1e-5f);
  }
  EXPECT_NEAR(directionalAlbedo(glm::vec3(1.0f), 0.0f, 1.0f, 0.7f, 256).x, 1.0f, 0.08f);
  // Light from below the surface reflects nothing.
  EXPECT_EQ(core::gltfBrdf(base, 0.0f, 0.5f, n, glm::vec3(0.0f, 0.0f, -1.0f), v), glm::vec3(0.0f));
}

}  // namespace
}  // namespace relief::test
