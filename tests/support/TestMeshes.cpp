// TestMeshes; see TestMeshes.h.
#include "support/TestMeshes.h"

#include "core/mesh/TangentFrames.h"

namespace relief::test {

core::Mesh mirroredQuads() {
  core::Mesh mesh;
  mesh.name = "mirrored";
  auto quad = [&mesh](float x0, float x1, float u0, float u1) {
    const auto base = std::uint32_t(mesh.vertices.size());
    const glm::vec3 up(0, 1, 0);
    mesh.vertices.push_back({{x0, 0, 1}, up, {u0, 0}, {}});
    mesh.vertices.push_back({{x1, 0, 1}, up, {u1, 0}, {}});
    mesh.vertices.push_back({{x1, 0, -1}, up, {u1, 1}, {}});
    mesh.vertices.push_back({{x0, 0, -1}, up, {u0, 1}, {}});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  };
  quad(-1.0f, 0.0f, 0.0f, 1.0f);
  quad(0.0f, 1.0f, 1.0f, 0.0f);  // mirrored in u
  core::computeTangentFrames(mesh);
  return mesh;
}

}  // namespace relief::test
