#!/usr/bin/env bash
# Fuzzes Relief's file readers with libFuzzer (clang from Debian: clang, libclang-rt-14-dev).
#   tools/fuzz/run.sh [SECONDS_PER_TARGET] [TARGET...]     (default 120 s, every target)
# Builds build/fuzz (RELIEF_FUZZ=ON: core and the targets only, with ASan and UBSan), then runs
# each target on a working copy of its committed corpus. Crashes, leaks, timeouts and
# out-of-memory inputs land in build/fuzz/findings/<target>/; add each one, once fixed, to
# tests/fuzz/corpus/<target>/ (named after the bug) so CTest replays it on every `make test`.
# With MERGE=1 the inputs that reach new code are merged into the committed corpus too.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-120}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(dds ktx2 png tiff exr preset gltf glb obj)
build=build/fuzz
if ! command -v clang++ >/dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  echo "run.sh: needs clang with libFuzzer: sudo apt-get install clang libclang-rt-14-dev" >&2
  exit 1
fi

CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DRELIEF_FUZZ=ON -DRELIEF_BUILD_TESTS=OFF -DRELIEF_BUILD_TOOLS=OFF >/dev/null
cmake --build "$build"

export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1
export LSAN_OPTIONS=suppressions=$PWD/tools/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
for target in "${targets[@]}"; do
  work=$build/work/$target
  findings=$build/findings/$target
  mkdir -p "$work" "$findings"
  cp -n tests/fuzz/corpus/"$target"/* "$work"/ 2>/dev/null || true
  echo "== $target: ${seconds} s"
  # -rss_limit_mb: readers must refuse what they cannot hold, so 2 GiB is a finding.
  # -timeout is wall-clock time: on a busy machine replay a timeout alone before trusting it.
  "$build/tests/fuzz/relief_fuzz_$target" "$work" -max_total_time="$seconds" -timeout=30 \
    -rss_limit_mb=2048 -max_len=16384 -artifact_prefix="$findings/" -print_final_stats=1 \
    2>&1 | grep -E '^#[0-9]+.*(DONE|pulse)|stat::|SUMMARY|ERROR|Test unit written' || true
  if [ "${MERGE:-0}" = 1 ]; then
    "$build/tests/fuzz/relief_fuzz_$target" -merge=1 tests/fuzz/corpus/"$target" "$work" \
      2>&1 | grep -E 'MERGE-OUTER: [0-9]+ new files' || true
  fi
done
echo "findings: $(find "$build/findings" -type f | wc -l) files in $build/findings"
