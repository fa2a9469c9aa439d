// Built-in meshes; see MeshPrimitives.h.
#include "core/mesh/MeshPrimitives.h"

#include "core/mesh/TangentFrames.h"

#include <array>
#include <cmath>
#include <numbers>

namespace relief::core::inline mesh {
namespace {

constexpr std::array kShapes = {PrimitiveShape::Plane, PrimitiveShape::Cube, PrimitiveShape::Sphere,
                                PrimitiveShape::Cylinder, PrimitiveShape::Torus};
constexpr std::array<std::string_view, 5> kShapeNames = {"plane", "cube", "sphere", "cylinder",
                                                         "torus"};

// Indices of a (columns+1) x (rows+1) vertex grid starting at `base`, two counter-clockwise
// triangles per cell when vertex (i+1, j) is to the right of (i, j) and (i, j+1) above it.
void appendGridIndices(Mesh& mesh, std::uint32_t base, int columns, int rows) {
  const auto row = std::uint32_t(columns + 1);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const std::uint32_t a = base + std::uint32_t(j) * row + std::uint32_t(i);
      const std::uint32_t b = a + 1, c = a + row + 1, d = a + row;
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  }
}

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
  appendGridIndices(mesh, base, segments, segments);
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

Mesh makeCube(float size, int segments) {
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
    appendGrid(mesh, origin, size * face.uAxis, size * face.vAxis, std::max(segments, 1));
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

Mesh makeCylinder(float radius, float height, int segments) {
  Mesh mesh;
  mesh.name = "cylinder";
  segments = std::max(segments, 3);
  const float pi = std::numbers::pi_v<float>;
  const float half = 0.5f * height;
  // Side: u = 2 * angle / 2pi (two repeats around), v from bottom to top.
  for (int j = 0; j <= 1; ++j) {
    for (int i = 0; i <= segments; ++i) {
      const float u = float(i) / float(segments);
      const float theta = u * 2.0f * pi;
      const glm::vec3 outward(std::sin(theta), 0.0f, std::cos(theta));
      Vertex vertex;
      vertex.position = radius * outward + glm::vec3(0.0f, j ? half : -half, 0.0f);
      vertex.normal = outward;
      vertex.uv = glm::vec2(2.0f * u, float(j));
      mesh.vertices.push_back(vertex);
    }
  }
  appendGridIndices(mesh, 0, segments, 1);
  // Caps: discs with planar UVs, counter-clockwise seen from outside.
  for (const float side : {1.0f, -1.0f}) {
    const auto centre = std::uint32_t(mesh.vertices.size());
    Vertex middle;
    middle.position = glm::vec3(0.0f, side * half, 0.0f);
    middle.normal = glm::vec3(0.0f, side, 0.0f);
    middle.uv = glm::vec2(0.5f);
    mesh.vertices.push_back(middle);
    for (int i = 0; i <= segments; ++i) {
      const float theta = float(i) / float(segments) * 2.0f * pi;
      Vertex rim;
      rim.position = glm::vec3(radius * std::sin(theta), side * half, radius * std::cos(theta));
      rim.normal = middle.normal;
      // Seen from above (+Y) u follows +X and v follows -Z, like the plane.
      rim.uv = glm::vec2(0.5f + 0.5f * std::sin(theta), 0.5f - 0.5f * side * std::cos(theta));
      mesh.vertices.push_back(rim);
    }
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t a = centre + 1 + std::uint32_t(i), b = a + 1;
      if (side > 0.0f) {
        mesh.indices.insert(mesh.indices.end(), {centre, a, b});
      } else {
        mesh.indices.insert(mesh.indices.end(), {centre, b, a});
      }
    }
  }
  computeTangentFrames(mesh);
  return mesh;
}

Mesh makeTorus(float ringRadius, float tubeRadius, int ringSegments, int tubeSegments) {
  Mesh mesh;
  mesh.name = "torus";
  ringSegments = std::max(ringSegments, 3);
  tubeSegments = std::max(tubeSegments, 3);
  const float pi = std::numbers::pi_v<float>;
  constexpr float kRingRepeats = 3.0f;  // keeps texels near square along the long ring
  for (int j = 0; j <= tubeSegments; ++j) {
    const float v = float(j) / float(tubeSegments);
    const float phi = v * 2.0f * pi - pi;  // around the tube, starting at the inner equator
    for (int i = 0; i <= ringSegments; ++i) {
      const float u = float(i) / float(ringSegments);
      const float theta = u * 2.0f * pi;  // along the ring, toward +X from +Z
      const glm::vec3 ringOut(std::sin(theta), 0.0f, std::cos(theta));
      const glm::vec3 normal = std::cos(phi) * ringOut + std::sin(phi) * glm::vec3(0, 1, 0);
      Vertex vertex;
      vertex.position = ringRadius * ringOut + tubeRadius * normal;
      vertex.normal = glm::normalize(normal);
      vertex.uv = glm::vec2(kRingRepeats * u, v);
      mesh.vertices.push_back(vertex);
    }
  }
  // u grows toward +X seen from +Z and v grows upward on the outside: counter-clockwise.
  appendGridIndices(mesh, 0, ringSegments, tubeSegments);
  computeTangentFrames(mesh);
  return mesh;
}

Mesh makePrimitive(PrimitiveShape shape) {
  switch (shape) {
    case PrimitiveShape::Plane:
      return makePlane(2.0f, kPrimitiveFaceSegments);
    case PrimitiveShape::Cube:
      return makeCube(1.6f, kPrimitiveFaceSegments);
    case PrimitiveShape::Sphere:
      return makeSphere();
    case PrimitiveShape::Cylinder:
      return makeCylinder();
    case PrimitiveShape::Torus:
      return makeTorus();
  }
  return makePlane();
}

}  // namespace relief::core::inline mesh
