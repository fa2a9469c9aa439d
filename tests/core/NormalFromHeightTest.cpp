// Normals from heights (reference 003, 1.4): exact on a tilted plane, pointing away from
// higher ground, and tileable when wrapping.
#include "core/generators/NormalFromHeight.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>

#include <cmath>

namespace relief::core {
namespace {

glm::vec3 decoded(const Image& normals, int x, int y) {
  const float* p = normals.pixel(x, y);
  return glm::vec3(p[0], p[1], p[2]) * 2.0f - 1.0f;
}

TEST(NormalFromHeight, TiltedPlaneGivesTheExactNormal) {
  // h rises by a per texel to the right and b per texel up the image (rows go down).
  const float a = 0.01f, b = 0.004f, strength = 20.0f;
  Image height(32, 32, 1);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x)
      height.at(x, y, 0) = 0.5f + a * float(x) - b * float(y);
  }
  const Image normals = normalMapFromHeight(height, {strength, EdgeMode::Clamp});
  const glm::vec3 expected = glm::normalize(glm::vec3(-strength * a, -strength * b, 1.0f));
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const glm::vec3 n = decoded(normals, x, y);
      EXPECT_NEAR(n.x, expected.x, 1e-5f);
      EXPECT_NEAR(n.y, expected.y, 1e-5f);
      EXPECT_NEAR(n.z, expected.z, 1e-5f);
    }
  }
  // Higher ground to the right: the normal leans left; higher up the image: it leans down.
  EXPECT_LT(expected.x, 0.0f);
  EXPECT_LT(expected.y, 0.0f);
}

TEST(NormalFromHeight, WrapTilesWithoutASeam) {
  // One period of a sine across the map: wrapped differences at the border equal the
  // interior's, so column 0 matches the analytic derivative like any other column.
  const int size = 64;
  Image height(size, 4, 1);
  const float k = 2.0f * 3.14159265f / float(size);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < size; ++x)
      height.at(x, y, 0) = 0.5f + 0.1f * std::sin(k * float(x));
  }
  const Image normals = normalMapFromHeight(height, {10.0f, EdgeMode::Wrap});
  for (int x : {0, 1, size / 2, size - 1}) {
    // Central difference of a sine: derivative times sin(k)/k.
    const float slope = 0.1f * std::cos(k * float(x)) * std::sin(k);
    const glm::vec3 expected = glm::normalize(glm::vec3(-10.0f * slope, 0.0f, 1.0f));
    EXPECT_NEAR(decoded(normals, x, 1).x, expected.x, 1e-5f) << "column " << x;
  }
}

TEST(NormalFromHeight, HandlesOneTexelMaps) {
  Image height(1, 1, 1);
  height.at(0, 0, 0) = 0.3f;
  for (EdgeMode edge : {EdgeMode::Wrap, EdgeMode::Clamp}) {
    const Image normals = normalMapFromHeight(height, {5.0f, edge});
    const glm::vec3 n = decoded(normals, 0, 0);
    EXPECT_NEAR(n.z, 1.0f, 1e-6f);
  }
}

}  // namespace
}  // namespace relief::core
