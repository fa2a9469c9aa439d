// The display transform: exposure in stops and the Khronos PBR Neutral tone mapper, against
// values worked by hand from the specification (KhronosGroup/ToneMapping, PBR_Neutral/README.md:
// F90 = 0.04, Ks = 0.76, Kd = 0.15).
#include "core/view/DisplayTransform.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace relief::core {
namespace {

void expectColor(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.r, expected.r, tolerance);
  EXPECT_NEAR(actual.g, expected.g, tolerance);
  EXPECT_NEAR(actual.b, expected.b, tolerance);
}

TEST(PbrNeutral, BelowTheKneeOnlyTheFloorMoves) {
  // min 0.2 > 2 F90: f = 0.04, p = 0.46 <= Ks: c - f.
  expectColor(pbrNeutral({0.5f, 0.3f, 0.2f}), {0.46f, 0.26f, 0.16f});
  // min 0.05 <= 2 F90: f = 0.05 - 0.05^2 / 0.16 = 0.034375.
  expectColor(pbrNeutral(glm::vec3(0.05f)), glm::vec3(0.015625f));
  expectColor(pbrNeutral(glm::vec3(0.0f)), glm::vec3(0.0f));
}

TEST(PbrNeutral, HighlightsRollOffTowardWhite) {
  // Grey 4: c - f = 3.96 = p; p_n = 1 - 0.24^2 / (3.96 + 1 - 1.52) = 0.9832558; a grey stays grey.
  expectColor(pbrNeutral(glm::vec3(4.0f)), glm::vec3(0.9832558f));
  // A red highlight: (2, 0.5, 0.5) - 0.04 -> p = 1.96, p_n = 1 - 0.0576 / 1.44 = 0.96,
  // g = 1 / (0.15 (1.96 - 0.96) + 1) = 1 / 1.15; out = (c - f) p_n / p g + p_n (1 - g): red
  // becomes p_n, the others rise toward it.
  const float g = 1.0f / 1.15f;
  const float low = 0.46f * 0.96f / 1.96f * g + 0.96f * (1.0f - g);
  expectColor(pbrNeutral({2.0f, 0.5f, 0.5f}), {0.96f, low, low});
  // Continuous at the knee and bounded by 1 however bright.
  // (slope 1 on both sides of it: inputs 2e-4 apart give outputs 2e-4 apart)
  expectColor(pbrNeutral(glm::vec3(0.7999f)), pbrNeutral(glm::vec3(0.8001f)), 2.5e-4f);
  EXPECT_LT(pbrNeutral(glm::vec3(1e6f)).r, 1.0f);
  float previous = 0.0f;
  for (float x = 0.0f; x < 20.0f; x += 0.01f) {
    const float y = pbrNeutral(glm::vec3(x)).r;
    EXPECT_GE(y, previous) << x;
    previous = y;
  }
}

// ACES filmic on greys, worked by hand from Hill's fit: both matrices' rows sum to 1, so a grey g
// stays grey and becomes the curve (v (v + 0.0245786) - 0.000090537) /
// (v (0.983729 v + 0.4329510) + 0.238081) at v = g / 0.6: 0.18 -> 0.21311, 1 -> 0.76340,
// 4 -> 0.95224. The curve tends to 1 / 0.983729 > 1, clamped to 1.
TEST(AcesFilmic, GreysFollowTheFittedCurveAndStayGrey) {
  expectColor(acesFilmic(glm::vec3(0.18f)), glm::vec3(0.21311f), 2e-4f);
  expectColor(acesFilmic(glm::vec3(1.0f)), glm::vec3(0.76340f), 2e-4f);
  expectColor(acesFilmic(glm::vec3(4.0f)), glm::vec3(0.95224f), 2e-4f);
  expectColor(acesFilmic(glm::vec3(1000.0f)), glm::vec3(1.0f), 1e-6f);
  expectColor(acesFilmic(glm::vec3(0.0f)), glm::vec3(0.0f), 1e-3f);
  float previous = 0.0f;
  for (float x = 0.0f; x < 20.0f; x += 0.05f) {
    const glm::vec3 y = acesFilmic({x, 0.5f * x, 0.1f * x});
    EXPECT_GE(y.r, previous) << x;
    EXPECT_LE(y.r, 1.0f);
    EXPECT_GE(std::min(y.g, y.b), 0.0f);
    previous = y.r;
  }
}

TEST(DisplayTransform, ExposureIsInStopsAndNamesRoundTrip) {
  DisplayTransform transform;
  transform.exposureEv = 1.0f;
  expectColor(applyDisplayTransform(transform, {0.1f, 0.2f, 0.3f}), {0.2f, 0.4f, 0.6f});
  transform.exposureEv = -2.0f;
  transform.toneMapper = ToneMapper::PbrNeutral;
  expectColor(applyDisplayTransform(transform, glm::vec3(2.0f)), pbrNeutral(glm::vec3(0.5f)));
  transform.toneMapper = ToneMapper::Aces;
  expectColor(applyDisplayTransform(transform, glm::vec3(4.0f)), acesFilmic(glm::vec3(1.0f)));
  for (ToneMapper mapper : allToneMappers())
    EXPECT_EQ(findToneMapper(toneMapperName(mapper)), mapper);
  EXPECT_FALSE(findToneMapper("filmic").has_value());
}

}  // namespace
}  // namespace relief::core
