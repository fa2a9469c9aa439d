// Tangent frames after reference 004: orthonormal, aligned with the UV derivatives, with the
// handedness that makes B = cross(N, T) * w point along +v, also where UVs are mirrored.
#include "core/mesh/MeshPrimitives.h"
#include "core/mesh/TangentFrames.h"
#include "support/TestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace relief::core {
namespace {

glm::vec3 bitangentOf(const Vertex& v) {
  return glm::cross(v.normal, glm::vec3(v.tangent)) * v.tangent.w;
}

// Every vertex: unit normal and tangent, tangent perpendicular to normal, w = +-1, finite.
void expectOrthonormal(const Mesh& mesh) {
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vertex& v = mesh.vertices[i];
    const glm::vec3 t(v.tangent);
    ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << i;
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f) << mesh.name << " vertex " << i;
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f) << mesh.name << " vertex " << i;
    EXPECT_NEAR(glm::dot(t, v.normal), 0.0f, 1e-5f) << mesh.name << " vertex " << i;
    EXPECT_EQ(std::abs(v.tangent.w), 1.0f) << mesh.name << " vertex " << i;
  }
}

// Every triangle: the frame's T follows dP/du and B follows dP/dv (the analytic derivatives
// of the triangle's affine UV map), and the triangle winds counter-clockwise around N.
void expectFramesFollowUvs(const Mesh& mesh) {
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vertex& a = mesh.vertices[mesh.indices[i]];
    const Vertex& b = mesh.vertices[mesh.indices[i + 1]];
    const Vertex& c = mesh.vertices[mesh.indices[i + 2]];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    ASSERT_NE(det, 0.0f);
    const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
    const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
    const glm::vec3 faceNormal = glm::cross(e1, e2);
    for (const Vertex* v : {&a, &b, &c}) {
      EXPECT_GT(glm::dot(glm::vec3(v->tangent), dPdu), 0.0f) << mesh.name << " triangle " << i / 3;
      EXPECT_GT(glm::dot(bitangentOf(*v), dPdv), 0.0f) << mesh.name << " triangle " << i / 3;
      EXPECT_GT(glm::dot(faceNormal, v->normal), 0.0f) << mesh.name << " triangle " << i / 3;
    }
  }
}

TEST(TangentFrames, PlaneHasTheTextbookFrame) {
  const Mesh plane = makePlane(2.0f, 1);
  for (const Vertex& v : plane.vertices) {
    EXPECT_NEAR(v.tangent.x, 1.0f, 1e-6f);
    EXPECT_NEAR(v.tangent.y, 0.0f, 1e-6f);
    EXPECT_NEAR(v.tangent.z, 0.0f, 1e-6f);
    EXPECT_EQ(v.tangent.w, 1.0f);
    // v runs away from a viewer on +Z: B = -Z.
    EXPECT_NEAR(bitangentOf(v).z, -1.0f, 1e-6f);
  }
}

TEST(TangentFrames, PrimitivesAreOrthonormalAndFollowTheirUvs) {
  for (PrimitiveShape shape : allPrimitiveShapes()) {
    const Mesh mesh = makePrimitive(shape);
    SCOPED_TRACE(mesh.name);
    expectOrthonormal(mesh);
    expectFramesFollowUvs(mesh);
  }
}

TEST(TangentFrames, MirroredUvsFlipTheHandedness) {
  const Mesh mesh = test::mirroredQuads();
  expectOrthonormal(mesh);
  expectFramesFollowUvs(mesh);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(mesh.vertices[i].tangent.w, 1.0f);
    EXPECT_NEAR(mesh.vertices[i].tangent.x, 1.0f, 1e-6f);
  }
  for (std::size_t i = 4; i < 8; ++i) {
    EXPECT_EQ(mesh.vertices[i].tangent.w, -1.0f);
    EXPECT_NEAR(mesh.vertices[i].tangent.x, -1.0f, 1e-6f);
    // Both halves agree on where +v is, so a normal map's +Y means the same on both.
    EXPECT_NEAR(bitangentOf(mesh.vertices[i]).z, -1.0f, 1e-6f);
  }
}

TEST(TangentFrames, DegenerateUvsGiveAValidFrameNotNaN) {
  Mesh mesh;
  const glm::vec3 normal = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
  // All three corners share one UV: the UV Jacobian is singular.
  mesh.vertices.push_back({{0, 0, 0}, normal, {0.5f, 0.5f}, {}});
  mesh.vertices.push_back({{1, 0, 0}, normal, {0.5f, 0.5f}, {}});
  mesh.vertices.push_back({{0, 0, 1}, normal, {0.5f, 0.5f}, {}});
  // A second triangle whose UVs are collinear.
  mesh.vertices.push_back({{0, 1, 0}, normal, {0.0f, 0.0f}, {}});
  mesh.vertices.push_back({{1, 1, 0}, normal, {1.0f, 1.0f}, {}});
  mesh.vertices.push_back({{0, 1, 1}, normal, {2.0f, 2.0f}, {}});
  mesh.indices = {0, 1, 2, 3, 4, 5};
  computeTangentFrames(mesh);
  expectOrthonormal(mesh);
}

TEST(TangentFrames, ZeroNormalDoesNotProduceNaN) {
  Mesh mesh;
  mesh.vertices.push_back({{0, 0, 0}, {0, 0, 0}, {0, 0}, {}});
  mesh.vertices.push_back({{1, 0, 0}, {0, 0, 0}, {1, 0}, {}});
  mesh.vertices.push_back({{0, 1, 0}, {0, 0, 0}, {0, 1}, {}});
  mesh.indices = {0, 1, 2};
  computeTangentFrames(mesh);
  expectOrthonormal(mesh);
}

}  // namespace
}  // namespace relief::core
