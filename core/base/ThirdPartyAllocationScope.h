// ThirdPartyAllocationScope: while one exists, LeakSanitizer ignores new allocations. Wrapped
// around single calls into a library with a known leak that LeakSanitizer cannot name in a
// suppression: OpenImageIO 2.4 loses an error string when libpng longjmps out of a damaged
// file (PNGInput::PngReadCallback -> ImageInput::geterror), when opening the file (its header
// chunks) as when reading pixels. libstdc++, where the string is allocated, has no frame pointers,
// so the sanitizer's stack stops there and tools/sanitizers/lsan.supp cannot match OpenImageIO
// (valgrind shows the full stack). Leak detection stays on for everything else. Without
// AddressSanitizer this is an empty object.
#pragma once

// GCC defines __SANITIZE_ADDRESS__; clang (the fuzz build) answers __has_feature instead.
#if defined(__SANITIZE_ADDRESS__)
#define RELIEF_HAS_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RELIEF_HAS_ASAN 1
#endif
#endif

#if defined(RELIEF_HAS_ASAN)
#include <sanitizer/lsan_interface.h>
#endif

namespace relief::core::inline base {

class ThirdPartyAllocationScope {
 public:
#if defined(RELIEF_HAS_ASAN)
  ThirdPartyAllocationScope() {
    __lsan_disable();
  }
  ~ThirdPartyAllocationScope() {
    __lsan_enable();
  }
#else
  // User-provided (not defaulted) so that a scope variable does not count as unused.
  ThirdPartyAllocationScope() {}  // NOLINT(modernize-use-equals-default)
#endif
  ThirdPartyAllocationScope(const ThirdPartyAllocationScope&) = delete;
  ThirdPartyAllocationScope& operator=(const ThirdPartyAllocationScope&) = delete;
};

}  // namespace relief::core::inline base
