// MeshImport; see MeshImport.h.
#include "core/mesh/MeshImport.h"

#include "core/base/InputFile.h"
#include "core/mesh/AssimpModule.h"
#include "core/mesh/GltfPreflight.h"
#include "core/mesh/TangentFrames.h"

#include <cmath>

namespace relief::core::inline mesh {

Result<ImportedMesh> importMesh(const std::string& path) {
  if (auto checked = checkInputFile(path, kMaxMeshFileBytes, "mesh file"); !checked)
    return makeError(checked.error());
  if (Status checked = preflightGltf(path); !checked)
    return makeError(checked.error());
  const Result<AssimpModule*> module = assimpModule(path + ": importing a mesh");
  if (!module)
    return makeError(module.error());
  Result<AssimpScene> scene = module.value()->read(path);
  if (!scene)
    return makeError(scene.error());
  const bool anyTriangles = scene->anyTriangles, allHaveUvs = scene->allHaveUvs;
  const bool allHaveTangents = scene->allHaveTangents;
  ImportedMesh result;
  Mesh& mesh = result.mesh;
  mesh = std::move(scene->mesh);

  if (!anyTriangles)
    return makeError(path + ": the file contains no triangles");
  // A NaN or infinite position would leave the mesh unframeable and the render silently empty.
  std::size_t nonFinite = 0;
  for (const Vertex& vertex : mesh.vertices) {
    const glm::vec3& p = vertex.position;
    nonFinite += (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) ? 0 : 1;
  }
  if (nonFinite > 0) {
    return makeError(path + ": " + std::to_string(nonFinite) + " of " +
                     std::to_string(mesh.vertices.size()) +
                     " vertices have non-finite positions (NaN or infinity)");
  }
  if (!allHaveUvs) {
    return makeError(path +
                     ": the mesh has no texture coordinates (UVs); Relief needs them to map the "
                     "material. Unwrap it in your modelling tool and export again.");
  }
  result.tangentsFromFile = allHaveTangents;
  if (allHaveTangents) {
    // Keep the file's tangents, made orthogonal to the (possibly smoothed) normals.
    for (Vertex& vertex : mesh.vertices) {
      glm::vec3 t = glm::vec3(vertex.tangent);
      t -= glm::dot(t, vertex.normal) * vertex.normal;
      if (glm::dot(t, t) < 1e-16f || !std::isfinite(t.x)) {
        result.tangentsFromFile = false;
        break;
      }
      vertex.tangent = glm::vec4(glm::normalize(t), vertex.tangent.w);
    }
  }
  if (!result.tangentsFromFile)
    computeTangentFrames(mesh);
  else
    computeUvScales(mesh);
  return result;
}

std::string meshFileFilter() {
  return "*.obj *.fbx *.gltf *.glb *.dae *.ply *.stl *.3ds";
}

}  // namespace relief::core::inline mesh
