// AssimpModule; see AssimpModule.h.
#include "core/mesh/AssimpModule.h"

#include "core/base/ModuleLoader.h"

namespace relief::core::inline mesh {

Result<AssimpModule*> assimpModule(const std::string& needs) {
  const Result<void*> entry = loadModuleEntry("librelief_assimp.so", "reliefAssimpModule", needs);
  if (!entry)
    return makeError(entry.error());
  using Entry = AssimpModule* (*)();
  return reinterpret_cast<Entry>(entry.value())();
}

}  // namespace relief::core::inline mesh
