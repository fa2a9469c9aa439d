// Mesh helpers; see Mesh.h.
#include "core/mesh/Mesh.h"

#include <algorithm>
#include <cmath>

namespace relief::core::inline mesh {

Bounds Mesh::bounds() const {
  if (vertices.empty())
    return {};
  Bounds box{vertices.front().position, vertices.front().position};
  for (const Vertex& vertex : vertices) {
    box.min = glm::min(box.min, vertex.position);
    box.max = glm::max(box.max, vertex.position);
  }
  const glm::vec3 center = box.center();
  for (const Vertex& vertex : vertices) {
    box.sphereRadius = std::max(box.sphereRadius, glm::length(vertex.position - center));
  }
  return box;
}

double worldUnitsPerUv(const Mesh& mesh) {
  double worldArea = 0.0;
  double uvArea = 0.0;
  for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
    const Vertex& a = mesh.vertices.at(mesh.indices[i]);
    const Vertex& b = mesh.vertices.at(mesh.indices[i + 1]);
    const Vertex& c = mesh.vertices.at(mesh.indices[i + 2]);
    worldArea +=
        0.5 * double(glm::length(glm::cross(b.position - a.position, c.position - a.position)));
    const glm::vec2 ab = b.uv - a.uv;
    const glm::vec2 ac = c.uv - a.uv;
    uvArea += 0.5 * std::abs(double(ab.x) * ac.y - double(ab.y) * ac.x);
  }
  return worldArea > 0.0 && uvArea > 0.0 ? std::sqrt(worldArea / uvArea) : 0.0;
}

}  // namespace relief::core::inline mesh
