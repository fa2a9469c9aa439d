#!/usr/bin/env bash
# docs/pipelines.md's example: docs/examples/materials.mk run with make -j2 on the three
# samples' heights (reduced to 256x256 to keep the test short), as a pipeline engineer would.
# Every output exists and reads back as what it should be, and a second make has nothing to do.
# Usage: pipeline_test.sh SOURCE_DIR RELIEF_CLI
set -euo pipefail
source=$1
cli=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() {
  echo "pipeline_test: $*" >&2
  exit 1
}
mkdir "$work/in"
for sample in bricks tiles cobblestones; do
  oiiotool "$source/samples/$sample/${sample}_height.png" --resize 256x256 -d uint16 \
    -o "$work/in/${sample}_height.png"
done
make -s -f "$source/docs/examples/materials.mk" -j2 IN="$work/in" OUT="$work/out" CLI="$cli"
for sample in bricks tiles cobblestones; do
  "$cli" info "$work/out/${sample}_normal.png" | grep -q "size: 256x256" \
    || fail "${sample}_normal.png is not a 256x256 image"
  "$cli" info "$work/out/${sample}_ao.png" | grep -q "channels: 1" \
    || fail "${sample}_ao.png is not a one-channel map"
  "$cli" info "$work/out/${sample}_normal.dds" | grep -q "format: BC5" \
    || fail "${sample}_normal.dds is not BC5: $("$cli" info "$work/out/${sample}_normal.dds")"
  "$cli" info "$work/out/${sample}_preview.png" | grep -q "size: 640x360" \
    || fail "${sample}_preview.png is not 640x360"
done
make -q -f "$source/docs/examples/materials.mk" IN="$work/in" OUT="$work/out" CLI="$cli" \
  || fail "a second make would redo work"
echo "pipeline_test: 12 files made for 3 materials with make -j2; a second run has nothing to do"
