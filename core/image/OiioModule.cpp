// OiioModule; see OiioModule.h.
#include "core/image/OiioModule.h"

#include "core/base/ModuleLoader.h"

namespace relief::core::inline image {

Result<OiioModule*> oiioModule(const std::string& needs) {
  const Result<void*> entry = loadModuleEntry("librelief_oiio.so", "reliefOiioModule", needs);
  if (!entry)
    return makeError(entry.error());
  using Entry = OiioModule* (*)();
  return reinterpret_cast<Entry>(entry.value())();
}

}  // namespace relief::core::inline image
