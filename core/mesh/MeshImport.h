// Meshes from files through Assimp (its module, AssimpModule.h): OBJ, FBX, glTF/GLB and what else
// Assimp reads. All meshes of the file are merged into one, in world space (node transforms
// applied). Tangents the file carries are kept; otherwise they are computed as reference 004
// describes (TangentFrames).
#pragma once

#include "core/base/Result.h"
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <string>

namespace relief::core::inline mesh {

// Assimp reads a whole file into memory; a mesh for a material preview is far smaller.
inline constexpr std::uintmax_t kMaxMeshFileBytes = std::uintmax_t(1) << 30;

struct ImportedMesh {
  Mesh mesh;
  bool tangentsFromFile = false;  // false: computed by computeTangentFrames
};

// Fails with a message naming the file for unreadable files, files without triangles and
// meshes without texture coordinates (a material cannot be mapped onto them).
Result<ImportedMesh> importMesh(const std::string& path);

// File name patterns of the formats offered in file dialogs.
std::string meshFileFilter();

}  // namespace relief::core::inline mesh
