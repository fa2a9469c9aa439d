// Mesh helpers; see Mesh.h.
#include "core/mesh/Mesh.h"

#include <algorithm>

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

}  // namespace relief::core::inline mesh
