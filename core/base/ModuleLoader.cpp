// ModuleLoader; see ModuleLoader.h.
#include "core/base/ModuleLoader.h"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <vector>

namespace relief::core::inline base {
namespace {

// The folders the dynamic loader searches for the executable's own libraries: its run path
// ($ORIGIN expanded), LD_LIBRARY_PATH and the system's. A plain dlopen("name") would search the
// caller's run path too, but under AddressSanitizer the caller is the sanitizer's dlopen
// interceptor in libasan.so, which has none: so the folders are listed here, from the program
// itself (glibc's dlinfo RTLD_DI_SERINFO), and the module is opened by its full path.
std::vector<std::string> programSearchPath() {
  std::vector<std::string> folders;
  void* program = dlopen(nullptr, RTLD_LAZY);
  Dl_serinfo size{};
  if (!program || dlinfo(program, RTLD_DI_SERINFOSIZE, &size) != 0)
    return folders;
  std::vector<unsigned char> buffer(size.dls_size);
  auto* info = reinterpret_cast<Dl_serinfo*>(buffer.data());
  if (dlinfo(program, RTLD_DI_SERINFOSIZE, info) == 0 &&
      dlinfo(program, RTLD_DI_SERINFO, info) == 0) {
    for (unsigned i = 0; i < info->dls_cnt; ++i)
      folders.emplace_back(info->dls_serpath[i].dls_name);
  }
  return folders;
}

// The first folder of the program's search path that holds `file`, as a full path; else the
// bare name (dlopen then fails with the loader's own reason).
std::string locate(const std::string& file) {
  for (const std::string& folder : programSearchPath()) {
    std::error_code error;
    const std::filesystem::path candidate = std::filesystem::path(folder) / file;
    if (std::filesystem::is_regular_file(candidate, error))
      return candidate.string();
  }
  return file;
}

}  // namespace

Result<void*> loadModuleEntry(const std::string& file, const char* entry,
                              const std::string& needs) {
  static std::mutex mutex;
  static std::map<std::string, Result<void*>> loaded;  // by file and entry; failures too
  const std::lock_guard lock(mutex);
  const std::string key = file + ":" + entry;
  if (auto known = loaded.find(key); known != loaded.end())
    return known->second;
  // RTLD_LOCAL: the module's libraries stay out of the global symbol scope. Modules are never
  // unloaded (objects they made may live until exit).
  void* handle = dlopen(locate(file).c_str(), RTLD_NOW | RTLD_LOCAL);
  Result<void*> result = makeError("");
  if (!handle) {
    const char* reason = dlerror();
    result = makeError(needs + " needs Relief's module " + file + ", which cannot be loaded (" +
                       (reason ? reason : "unknown reason") +
                       "); the installation is incomplete: reinstall Relief");
  } else if (void* symbol = dlsym(handle, entry); !symbol) {
    result = makeError(needs + " needs Relief's module " + file + ", which lacks " + entry +
                       " (a module of another Relief version?); reinstall Relief");
  } else {
    result = symbol;
  }
  loaded.emplace(key, result);
  return result;
}

}  // namespace relief::core::inline base
