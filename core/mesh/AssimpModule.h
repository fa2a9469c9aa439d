// What Relief asks of Assimp, as an interface of plain types: the module librelief_assimp.so
// implements it (AssimpPlugin.cpp, the only code that includes Assimp) and is loaded the first
// time a mesh file is imported (core/base/ModuleLoader.h), so a run that never imports a mesh
// never maps Assimp and its libraries. Both sides are built from this header by the same
// compiler, so the classes may carry std types.
#pragma once

#include "core/base/Result.h"
#include "core/mesh/Mesh.h"

#include <string>

namespace relief::core::inline mesh {

// Every triangle mesh of a file, merged in world space (node transforms applied), and what
// the file lacked. Tangents are the file's where it has them (see `allHaveTangents`).
struct AssimpScene {
  Mesh mesh;
  bool anyTriangles = false;
  bool allHaveUvs = true;  // meshes without UVs are left out of `mesh`
  bool allHaveTangents = true;
};

class AssimpModule {
 public:
  virtual ~AssimpModule() = default;
  // Reads the file; an error names it and gives Assimp's reason.
  virtual Result<AssimpScene> read(const std::string& path) = 0;
};

// The module, loaded on the first call; an error says why it cannot be loaded and names `needs`.
Result<AssimpModule*> assimpModule(const std::string& needs);

}  // namespace relief::core::inline mesh

// The module's entry point.
extern "C" relief::core::AssimpModule* reliefAssimpModule();
