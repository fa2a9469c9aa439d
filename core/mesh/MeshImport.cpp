// MeshImport; see MeshImport.h.
#include "core/mesh/MeshImport.h"

#include "core/base/InputFile.h"
#include "core/mesh/GltfPreflight.h"
#include "core/mesh/TangentFrames.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cmath>
#include <filesystem>
#include <functional>

namespace relief::core::inline mesh {
namespace {

glm::mat4 toGlm(const aiMatrix4x4& m) {
  // aiMatrix4x4 is row-major; glm is column-major.
  return glm::transpose(glm::mat4(m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3,
                                  m.c4, m.d1, m.d2, m.d3, m.d4));
}

}  // namespace

Result<ImportedMesh> importMesh(const std::string& path) {
  if (auto checked = checkInputFile(path, kMaxMeshFileBytes, "mesh file"); !checked)
    return makeError(checked.error());
  if (Status checked = preflightGltf(path); !checked)
    return makeError(checked.error());
  Assimp::Importer importer;
  // Our own tangents unless the file has them, so do not ask Assimp to compute any.
  const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                         aiProcess_GenSmoothNormals | aiProcess_SortByPType |
                         aiProcess_ValidateDataStructure;
  const aiScene* scene = importer.ReadFile(path, flags);
  if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
    return makeError(path + ": cannot read as a mesh (" + importer.GetErrorString() + ")");
  }

  ImportedMesh result;
  Mesh& mesh = result.mesh;
  mesh.name = std::filesystem::path(path).stem().string();
  bool anyTriangles = false;
  bool allHaveUvs = true;
  bool allHaveTangents = true;
  std::function<void(const aiNode*, const glm::mat4&)> visit = [&](const aiNode* node,
                                                                   const glm::mat4& parent) {
    const glm::mat4 transform = parent * toGlm(node->mTransformation);
    const glm::mat3 normalTransform = glm::transpose(glm::inverse(glm::mat3(transform)));
    for (unsigned k = 0; k < node->mNumMeshes; ++k) {
      const aiMesh* source = scene->mMeshes[node->mMeshes[k]];
      if (!(source->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
        continue;
      anyTriangles = true;
      if (!source->HasTextureCoords(0)) {
        allHaveUvs = false;
        continue;
      }
      allHaveTangents = allHaveTangents && source->HasTangentsAndBitangents();
      const auto base = std::uint32_t(mesh.vertices.size());
      for (unsigned i = 0; i < source->mNumVertices; ++i) {
        Vertex vertex;
        const aiVector3D& p = source->mVertices[i];
        vertex.position = glm::vec3(transform * glm::vec4(p.x, p.y, p.z, 1.0f));
        if (source->HasNormals()) {
          const aiVector3D& n = source->mNormals[i];
          vertex.normal = glm::normalize(normalTransform * glm::vec3(n.x, n.y, n.z));
        }
        const aiVector3D& uv = source->mTextureCoords[0][i];
        vertex.uv = glm::vec2(uv.x, uv.y);
        if (source->HasTangentsAndBitangents()) {
          const aiVector3D& t = source->mTangents[i];
          const aiVector3D& b = source->mBitangents[i];
          const glm::vec3 tangent = glm::mat3(transform) * glm::vec3(t.x, t.y, t.z);
          const glm::vec3 bitangent = glm::mat3(transform) * glm::vec3(b.x, b.y, b.z);
          const float w = glm::dot(glm::cross(vertex.normal, tangent), bitangent) < 0 ? -1.f : 1.f;
          vertex.tangent = glm::vec4(tangent, w);
        }
        mesh.vertices.push_back(vertex);
      }
      for (unsigned f = 0; f < source->mNumFaces; ++f) {
        const aiFace& face = source->mFaces[f];
        if (face.mNumIndices != 3)
          continue;
        for (unsigned c = 0; c < 3; ++c)
          mesh.indices.push_back(base + face.mIndices[c]);
      }
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      visit(node->mChildren[c], transform);
  };
  visit(scene->mRootNode, glm::mat4(1.0f));

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
  return result;
}

std::string meshFileFilter() {
  return "*.obj *.fbx *.gltf *.glb *.dae *.ply *.stl *.3ds";
}

}  // namespace relief::core::inline mesh
