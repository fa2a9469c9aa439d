// Sanitizer runtime defaults, compiled into every executable of a sanitizer build (see
// relief_target_defaults in cmake/ReliefTargetDefaults.cmake), so tests, the CLI processes they
// start and a developer's own runs all get them. ASAN_OPTIONS in the environment still overrides
// any flag set here.
//
// intercept_tls_get_addr=0: the sanitizer runtimes of GCC up to 13 and LLVM up to 16 (Debian 12
// ships GCC 12 and clang 14) intercept __tls_get_addr and take any dynamic TLS block whose start
// lies 16 bytes past a 4 KiB boundary for a glibc 2.19 block with a header in front, reading the
// two words before it as the block's start and size. glibc 2.25 dropped that header, so a block
// malloc'd at that offset by chance gives LeakSanitizer a bogus range; its stop-the-world tracer
// then faults at exit ("Tracer caught signal 11 ... LeakSanitizer has encountered a fatal
// error") after the program itself has finished and passed. CI saw it in three of 264 tests in
// one run (and once or twice in earlier runs), all in processes that drew with Mesa's llvmpipe,
// whose dlopen'd driver threads hold dynamic TLS; it is too rare to reproduce on demand (none
// in 150 runs of one such test here), as a chance malloc offset would be.
// Without the interceptor LeakSanitizer does not scan dlopen'd libraries' dynamic TLS; those
// libraries are Mesa's and LLVM's, whose allocations tools/sanitizers/lsan.supp suppresses.
extern "C" __attribute__((visibility("default"), used)) const char* __asan_default_options() {
  return "intercept_tls_get_addr=0";
}
