// Built-in meshes; see MeshPrimitives.h.
#include "core/MeshPrimitives.h"

#include "core/TangentFrames.h"

#include <array>
#include <cmath>
#include <numbers>

namespace relief::core {
namespace {

constexpr std::array kShapes = {PrimitiveShape::Plane, PrimitiveShape::Cube,
                                PrimitiveShape::Sphere};
constexpr std::array<std::string_view, 3> kShapeNames = {"plane", "cube", "sphere"};

// Appends a (segments+1)^2 grid spanning origin + s*uAxis + t*vAxis for s, t in [0, 1], with
// UV (s, t). uAxis x vAxis is the face normal, which makes the triangles counter-clockwise.
void appendGrid(Mesh& mesh, const glm::vec3& origin, const glm::vec3& uAxis, const glm::vec3& vAxis,
                int segments) {
  const glm::vec3 normal = glm::normalize(glm::cross(uAxis, vAxis));
  const auto base = std::uint32_t(mesh.vertices.size());
  for (int j = 0; j <= segments; ++j) {
    for (int i = 0; i <= segments; ++i) {
      const float s = float(i) / float(segments);
      const float t = float(j) / float(segments);
      Vertex vertex;
      vertex.position = origin + s * uAxis + t * vAxis;
      vertex.normal = normal;
      vertex.uv = glm::vec2(s, t);
      mesh.vertices.push_back(vertex);
    }
  }
  const auto row = std::uint32_t(segments + 1);
  for (int j = 0; j < segments; ++j) {
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t a = base + std::uint32_t(j) * row + std::uint32_t(i);
      const std::uint32_t b = a + 1, c = a + row + 1, d = a + row;
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  }
}

}  // namespace

std::span<const PrimitiveShape> allPrimitiveShapes() {
  return kShapes;
}

std::string_view primitiveShapeName(PrimitiveShape shape) {
  return kShapeNames[std::size_t(shape)];
}

std::optional<PrimitiveShape> findPrimitiveShape(std::string_view name) {
  for (PrimitiveShape shape : kShapes) {
    if (primitiveShapeName(shape) == name)
      return shape;
  }
  return std::nullopt;
}

Mesh makePlane(float size, int segments) {
  Mesh mesh;
  mesh.name = "plane";
  const float half = 0.5f * size;
  appendGrid(mesh, glm::vec3(-half, 0.0f, half), glm::vec3(size, 0.0f, 0.0f),
             glm::vec3(0.0f, 0.0f, -size), std::max(segments, 1));
  computeTangentFrames(mesh);
  return mesh;
}

Mesh makeCube(float size) {
  Mesh mesh;
  mesh.name = "cube";
  const float h = 0.5f * size;
  struct Face {
    glm::vec3 normal, uAxis, vAxis;
  };
  // uAxis x vAxis = normal for every face (counter-clockwise from outside).
  const std::array<Face, 6> faces = {{
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},
      {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
      {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}},
      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
  }};
  for (const Face& face : faces) {
    const glm::vec3 origin = h * (face.normal - face.uAxis - face.vAxis);
    appendGrid(mesh, origin, size * face.uAxis, size * face.vAxis, 1);
  }
  computeTangentFrames(mesh);
  return mesh;
}

Mesh makeSphere(float radius, int segments, int rings) {
  Mesh mesh;
  mesh.name = "sphere";
  segments = std::max(segments, 3);
  rings = std::max(rings, 2);
  const float pi = std::numbers::pi_v<float>;
  for (int j = 0; j <= rings; ++j) {
    const float v = float(j) / float(rings);
    const float phi = (v - 0.5f) * pi;  // latitude, -pi/2 at the south pole
    for (int i = 0; i <= segments; ++i) {
      const float u = float(i) / float(segments);
      const float theta = u * 2.0f * pi;  // longitude, 0 facing +Z, growing toward +X
      const glm::vec3 direction(std::cos(phi) * std::sin(theta), std::sin(phi),
                                std::cos(phi) * std::cos(theta));
      Vertex vertex;
      vertex.position = radius * direction;
      vertex.normal = direction;
      vertex.uv = glm::vec2(u, v);
      mesh.vertices.push_back(vertex);
    }
  }
  const auto row = std::uint32_t(segments + 1);
  for (int j = 0; j < rings; ++j) {
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t a = std::uint32_t(j) * row + std::uint32_t(i);
      const std::uint32_t b = a + 1, c = a + row + 1, d = a + row;
      // The pole rows have zero-area triangles; leave them out.
      if (j > 0)
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
      if (j < rings - 1)
        mesh.indices.insert(mesh.indices.end(), {a, c, d});
    }
  }
  computeTangentFrames(mesh);
  return mesh;
}

Mesh makePrimitive(PrimitiveShape shape) {
  switch (shape) {
    case PrimitiveShape::Plane:
      return makePlane();
    case PrimitiveShape::Cube:
      return makeCube();
    case PrimitiveShape::Sphere:
      return makeSphere();
  }
  return makePlane();
}

}  // namespace relief::core
