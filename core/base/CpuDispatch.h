// Running a hot loop with AVX2 where the CPU has it. The build targets the x86-64 baseline
// (SSE2) so the package runs on any x86-64; a function written twice, once as
// [[gnu::target("avx2")]], is chosen at run time by cpuHasAvx2(). FMA is deliberately not
// enabled: contracting a * b + c changes rounding, and both versions must write the same bytes
// on every machine. Elsewhere (other CPUs, other compilers, or RELIEF_NO_CPU_DISPATCH defined to
// try the baseline path) RELIEF_HAS_AVX2_DISPATCH is 0.
#pragma once

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(RELIEF_NO_CPU_DISPATCH)
#define RELIEF_HAS_AVX2_DISPATCH 1
#else
#define RELIEF_HAS_AVX2_DISPATCH 0
#endif

#if RELIEF_HAS_AVX2_DISPATCH
namespace relief::core {
inline bool cpuHasAvx2() {
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
}
}  // namespace relief::core
#endif
