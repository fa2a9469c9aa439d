// Tangent frames after reference 004: orthonormal, aligned with the UV derivatives, with the
// handedness that makes B = cross(N, T) * w point along +v, also where UVs are mirrored.
#include "core/mesh/MeshPrimitives.h"
#include "core/mesh/TangentFrames.h"
#include "support/TestMeshes.h"

#include <gtest/gtest.h>

#include <algorithm>
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

// uvScale: world units per unit of u and of v, the lengths of dP/du and dP/dv. The 2x2 plane
// maps UV 0..1 over 2 units both ways; a sphere of radius r maps u once around a parallel of
// circumference 2 pi r cos(latitude) and v from pole to pole, pi r. Its triangles are chords:
// each reads the parallel of its upper or lower row, and a vertex averages as many above as
// below, within 0.2% on 96 segments and 48 rings. A vertex on the UV seam has the triangles of
// one side only, two on its own row and one on the next: off by about tan(latitude) x the
// rows' spacing / 3 (3% at 60 degrees). The parallax marches give heights one world depth with
// them (shaders/include/displaced_position.glsl, toUvHeightSpace).
TEST(TangentFrames, UvScalesAreTheTexelsWorldSize) {
  for (const Vertex& v : makePlane(2.0f, 3).vertices) {
    EXPECT_NEAR(v.uvScale.x, 2.0f, 1e-5f);
    EXPECT_NEAR(v.uvScale.y, 2.0f, 1e-5f);
  }
  const float radius = 1.5f;
  const float pi = 3.14159265f;
  const Mesh sphere = makeSphere(radius, 96, 48);
  int checked = 0;
  for (const Vertex& v : sphere.vertices) {
    const float latitude = std::asin(std::clamp(v.normal.y, -1.0f, 1.0f));
    if (std::abs(latitude) > 1.2f)
      continue;  // the rows next to the poles: fans of triangles, not quads
    const bool onSeam = v.uv.x == 0.0f || v.uv.x == 1.0f;
    const float parallel = 2.0f * pi * radius * std::cos(latitude);
    const float rowSpacing = pi / 48.0f;
    const float tolerance =
        onSeam ? parallel * (std::tan(std::abs(latitude)) * rowSpacing / 3.0f + 0.002f)
               : 0.002f * parallel;
    EXPECT_NEAR(v.uvScale.x, parallel, tolerance) << "latitude " << latitude << " u " << v.uv.x;
    EXPECT_NEAR(v.uvScale.y, pi * radius, 0.002f * pi * radius) << "latitude " << latitude;
    ++checked;
  }
  EXPECT_GT(checked, 3000);
  // Mirrored halves: the same size whichever way u runs.
  for (const Vertex& v : test::mirroredQuads().vertices) {
    EXPECT_NEAR(v.uvScale.x, 1.0f, 1e-5f);
    EXPECT_NEAR(v.uvScale.y, 2.0f, 1e-5f);
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
