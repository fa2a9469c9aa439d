// Fuzz target for mesh import (core/mesh/GltfPreflight, MeshImport over Assimp): the glTF
// checks made before Assimp recurses, then the import, finite positions and tangent frames.
// RELIEF_FUZZ_EXTENSION is "gltf", "glb" or "obj".
#include "FuzzInput.h"

#include "core/mesh/MeshImport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = relief::fuzz::writeFuzzInput(data, size, RELIEF_FUZZ_EXTENSION);
  (void)relief::core::importMesh(path);
  return 0;
}
