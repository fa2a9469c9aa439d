#!/usr/bin/env bash
# tools/check-structure.py passes on the source tree and fails, naming file and line, on a copy
# of core/ with one include running back up and one `default:` in a switch over MapSlot.
set -euo pipefail
source_root=$1
checker="$source_root/tools/check-structure.py"

"$checker" "$source_root"

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/core/material" "$scratch/core/preset" "$scratch/renderer" "$scratch/ui" \
  "$scratch/app"
# material sits below preset: this include runs back up.
printf '#include "core/preset/MaterialPreset.h"\n' > "$scratch/core/material/Bad.cpp"
cat > "$scratch/renderer/BadSwitch.cpp" <<'CPP'
int f(MapSlot slot) {
  switch (slot) {
    case MapSlot::Color:
      return 1;
    default:  // a new slot would silently land here
      return 0;
  }
}
// A switch over something else may keep its default.
int g(int n) {
  switch (n) {
    case 1:
      return 1;
    default:
      return 0;
  }
}
CPP
if output=$("$checker" "$scratch"); then
  echo "FAIL: the checker passed a tree that breaks both rules"
  exit 1
fi
echo "$output"
grep -q "core/material/Bad.cpp:1: core/material includes core/preset" <<<"$output" ||
  { echo "FAIL: the back-up include was not reported"; exit 1; }
grep -q "renderer/BadSwitch.cpp:5: \`default:\` in a switch over MapSlot" <<<"$output" ||
  { echo "FAIL: the default in a MapSlot switch was not reported"; exit 1; }
[ "$(grep -c 'default' <<<"$output")" -eq 1 ] ||
  { echo "FAIL: a switch over an int was reported"; exit 1; }
echo "check_structure_test: passed"
