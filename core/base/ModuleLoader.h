// Relief's optional modules: the parts that need a large library (OpenImageIO's readers of
// JPEG, TGA, TIFF, EXR and HDR, Assimp's mesh importers) are built as shared objects of their
// own and loaded the first time a file needs them. A run that reads only PNG, DDS and KTX2 then
// never maps those libraries: OpenImageIO alone pulls in 260 shared libraries, which took
// 0.45 s of every relief-cli process before main (docs/architecture.md, "Start-up").
//
// Modules are found in the folders the executable's run path names: the build tree's module
// folder in a build, $ORIGIN/../lib/<arch>/relief once installed (set in
// cmake/ReliefTargetDefaults.cmake).
#pragma once

#include "core/base/Result.h"

#include <string>

namespace relief::core::inline base {

// The module's entry point `entry` (an extern "C" function), loading the module `file` (e.g.
// "librelief_oiio.so") on the first call; later calls return the same. `needs` says what the
// module is for, for the message when it cannot be loaded ("reading TGA files"). Thread-safe.
Result<void*> loadModuleEntry(const std::string& file, const char* entry, const std::string& needs);

}  // namespace relief::core::inline base
