#!/usr/bin/env bash
# The whole test suite, as CI runs it: formatting check, a strict build (warnings are errors)
# with AddressSanitizer and UndefinedBehaviorSanitizer, then every CTest test under Xvfb with
# Mesa's llvmpipe. Extra arguments go to ctest (e.g. -L unit, -R Lighting).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build/test
jobs=$(nproc)

tools/check-format.sh

# -g1 (line tables: sanitizer reports keep file and line) compiles a quarter faster than -g,
# which keeps CI's fresh build within its time budget; reconfigure with -g to debug variables.
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
  -DRELIEF_STRICT=ON -DRELIEF_SANITIZE=ON -DRELIEF_BUILD_TESTS=ON
cmake --build "$build" -j "$jobs"
# The glTF export test's validator; when npm cannot reach its registry the test says SKIPPED.
tools/gltf-validator/setup.sh "$build"

# Qt wants a private runtime folder; tests get a fresh one per run.
runtime=$(mktemp -d)
chmod 700 "$runtime"
trap 'rm -rf "$runtime"' EXIT
export XDG_RUNTIME_DIR="$runtime"
export QT_QPA_PLATFORM=xcb

start=$(date +%s)
# -noreset: an X server resets when its last client disconnects, and a client connecting during
# the reset is refused. Between two test processes Xvfb often has no client, and a fresh-clone
# run once failed that way ("cannot connect to the X display ':99'" in cli.pipeline_test).
xvfb-run -a -s '-screen 0 1600x1000x24 -noreset' \
  ctest --test-dir "$build" --output-on-failure -j "$jobs" "$@"
echo "run-tests: all tests passed in $(( $(date +%s) - start )) s"
