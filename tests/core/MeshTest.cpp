// core::worldUnitsPerUv, the displacement technique's heights-to-world factor, against the
// areas of shapes known in closed form.
#include "core/mesh/Mesh.h"
#include "core/mesh/MeshPrimitives.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace relief::core {
namespace {

TEST(WorldUnitsPerUv, APlaneMappedOnceIsItsSideLength) {
  EXPECT_NEAR(worldUnitsPerUv(makePlane(2.0f, 1)), 2.0, 1e-6);
  EXPECT_NEAR(worldUnitsPerUv(makePlane(3.0f, 7)), 3.0, 1e-5);
}

TEST(WorldUnitsPerUv, ASphereIsTheRootOfItsAreaOverTheUnitSquare) {
  // A UV sphere maps its whole surface, 4 pi r^2, onto the unit UV square once, except that
  // each of the two pole rows keeps one triangle per cell (the other has no area): 1 - 1/48 of
  // the square for 48 rings. The flat triangles of 96 x 48 segments hold 0.14% less area than
  // the sphere, so the factor is 0.07% low.
  const double radius = 1.5;
  const double expected = std::sqrt(4.0 * std::numbers::pi / (1.0 - 1.0 / 48.0)) * radius;
  EXPECT_NEAR(worldUnitsPerUv(makeSphere(float(radius))), expected, 0.002 * expected);
}

TEST(WorldUnitsPerUv, WithoutAreaItIsZero) {
  EXPECT_EQ(worldUnitsPerUv(Mesh{}), 0.0);
  Mesh collapsed = makePlane();
  for (Vertex& vertex : collapsed.vertices)
    vertex.uv = glm::vec2(0.25f, 0.5f);
  EXPECT_EQ(worldUnitsPerUv(collapsed), 0.0);
}

}  // namespace
}  // namespace relief::core
