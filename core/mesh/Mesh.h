// Mesh: indexed triangles with positions, normals, UVs and tangent frames (tangent.xyz plus
// handedness in tangent.w; bitangent = cross(N, T) * w, reference 004).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace relief::core::inline mesh {

struct Vertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec2 uv{0.0f};
  glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f};
  // World units per unit of u and of v at the vertex (the lengths of dP/du and dP/dv, averaged
  // over its triangles; computeUvScales): the parallax marches' texel shape (toUvHeightSpace in
  // shaders/include/displaced_position.glsl). 0: unknown, the marches take texels as square.
  glm::vec2 uvScale{0.0f};
};

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  // Largest distance of a vertex from center(): the radius of a sphere around the box centre
  // that holds the mesh (tighter than the box's half-diagonal for round meshes).
  float sphereRadius = 0.0f;
  glm::vec3 center() const { return 0.5f * (min + max); }
};

struct Mesh {
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;  // three per triangle

  std::size_t triangleCount() const { return indices.size() / 3; }
  Bounds bounds() const;
};

// World length of one UV unit over the whole mesh: the square root of its world area over its
// UV area, 0 when either is 0. The displacement technique moves vertices by heights measured in
// UV units with this one factor (not a per-triangle one), so the triangles either side of an
// edge move its vertices alike and the displaced surface has no cracks.
double worldUnitsPerUv(const Mesh& mesh);

}  // namespace relief::core::inline mesh
