// The Assimp module (librelief_assimp.so): AssimpModule.h implemented with Assimp 5. Built as a
// shared object of its own and loaded on demand (core/base/ModuleLoader.h); it uses only
// header-only parts of core (Result, Mesh's data), never core's compiled code.
#include "core/mesh/AssimpModule.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <filesystem>
#include <functional>

namespace relief::core::inline mesh {
namespace {

glm::mat4 toGlm(const aiMatrix4x4& m) {
  // aiMatrix4x4 is row-major; glm is column-major.
  return glm::transpose(glm::mat4(m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3,
                                  m.c4, m.d1, m.d2, m.d3, m.d4));
}

class Module final : public AssimpModule {
 public:
  Result<AssimpScene> read(const std::string& path) override {
    Assimp::Importer importer;
    // Relief's own tangents unless the file has them, so do not ask Assimp to compute any.
    const unsigned flags = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                           aiProcess_GenSmoothNormals | aiProcess_SortByPType |
                           aiProcess_ValidateDataStructure;
    const aiScene* scene = importer.ReadFile(path, flags);
    if (!scene || !scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
      return makeError(path + ": cannot read as a mesh (" + importer.GetErrorString() + ")");
    }
    AssimpScene result;
    Mesh& mesh = result.mesh;
    mesh.name = std::filesystem::path(path).stem().string();
    std::function<void(const aiNode*, const glm::mat4&)> visit = [&](const aiNode* node,
                                                                     const glm::mat4& parent) {
      const glm::mat4 transform = parent * toGlm(node->mTransformation);
      const glm::mat3 normalTransform = glm::transpose(glm::inverse(glm::mat3(transform)));
      for (unsigned k = 0; k < node->mNumMeshes; ++k) {
        const aiMesh* source = scene->mMeshes[node->mMeshes[k]];
        if (!(source->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
          continue;
        result.anyTriangles = true;
        if (!source->HasTextureCoords(0)) {
          result.allHaveUvs = false;
          continue;
        }
        result.allHaveTangents = result.allHaveTangents && source->HasTangentsAndBitangents();
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
            const float w =
                glm::dot(glm::cross(vertex.normal, tangent), bitangent) < 0 ? -1.f : 1.f;
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
    return result;
  }
};

}  // namespace
}  // namespace relief::core::inline mesh

extern "C" __attribute__((visibility("default"))) relief::core::AssimpModule* reliefAssimpModule() {
  static relief::core::mesh::Module module;
  return &module;
}
