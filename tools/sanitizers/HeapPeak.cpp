// The peak of a process's live heap bytes, counted through the sanitizer runtime's malloc and
// free hooks and written at exit to the file named by RELIEF_HEAP_PEAK_FILE (nothing happens
// when it is unset). Compiled, like SanitizerDefaults.cpp, into every executable of a sanitizer
// build (relief_target_defaults in cmake/ReliefTargetDefaults.cmake); release builds carry
// none of it.
//
// Why not the peak resident set (wait4's ru_maxrss)? It also counts what the allocator, the
// sanitizer's shadow memory and its quarantine hold back, which vary with the thread count and
// the runtime's version: tests/cli/LargeMapTest.cpp bounded it once and failed by 3% on one run
// and passed on the next. The bytes the program asked for and still holds are what its code
// controls; this counts exactly those, whatever the allocator does with them.
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>

// The sanitizer runtime's allocator interface (LLVM's sanitizer/allocator_interface.h, which GCC
// 12 does not install; both runtimes export these functions).
extern "C" {
int __sanitizer_get_ownership(const volatile void* pointer);
std::size_t __sanitizer_get_allocated_size(const volatile void* pointer);
int __sanitizer_install_malloc_and_free_hooks(void (*onMalloc)(const volatile void*, std::size_t),
                                              void (*onFree)(const volatile void*));
}

namespace {

std::atomic<long long> g_liveBytes{0};
std::atomic<long long> g_peakBytes{0};
const char* g_reportPath = nullptr;

void countAllocation(const volatile void*, std::size_t size) {
  const long long live =
      g_liveBytes.fetch_add(static_cast<long long>(size), std::memory_order_relaxed) +
      static_cast<long long>(size);
  long long peak = g_peakBytes.load(std::memory_order_relaxed);
  while (live > peak && !g_peakBytes.compare_exchange_weak(peak, live, std::memory_order_relaxed)) {
  }
}

// The runtime calls the free hook before it releases the block, so its size is still known.
void countRelease(const volatile void* pointer) {
  const void* block = const_cast<const void*>(pointer);
  if (block && __sanitizer_get_ownership(block)) {
    g_liveBytes.fetch_sub(static_cast<long long>(__sanitizer_get_allocated_size(block)),
                          std::memory_order_relaxed);
  }
}

__attribute__((constructor(101))) void startCounting() {
  g_reportPath = std::getenv("RELIEF_HEAP_PEAK_FILE");
  if (g_reportPath && *g_reportPath)
    __sanitizer_install_malloc_and_free_hooks(countAllocation, countRelease);
}

// Run after the program's own static destructors (a lower priority runs later).
__attribute__((destructor(101))) void reportPeak() {
  if (!g_reportPath || !*g_reportPath)
    return;
  if (std::FILE* report = std::fopen(g_reportPath, "w")) {
    std::fprintf(report, "%lld\n", g_peakBytes.load());
    std::fclose(report);
  }
}

}  // namespace
