#!/usr/bin/env bash
# Installs the Khronos glTF validator (npm package gltf-validator, pinned) into
# <build>/gltf-validator, where the export tests look for it. When npm or its registry cannot be
# reached, writes the reason to <build>/gltf-validator/UNAVAILABLE instead of failing: the
# glTF test then reports SKIPPED with that reason rather than passing silently.
# Usage: tools/gltf-validator/setup.sh <build folder>
set -uo pipefail
version="2.0.0-dev.3.10"
build=${1:?usage: setup.sh <build folder>}
target="$build/gltf-validator"
mkdir -p "$target"
rm -f "$target/UNAVAILABLE"

if [ -f "$target/node_modules/gltf-validator/package.json" ] &&
   grep -q "\"version\": \"$version\"" "$target/node_modules/gltf-validator/package.json"; then
  echo "gltf-validator: $version already installed in $target"
  exit 0
fi
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "node or npm is not installed (tools/install-deps.sh installs them)" > "$target/UNAVAILABLE"
  echo "gltf-validator: $(cat "$target/UNAVAILABLE")" >&2
  exit 0
fi
if ! log=$(timeout 300 npm install --no-audit --no-fund --silent --prefix "$target" \
             "gltf-validator@$version" 2>&1); then
  printf 'npm install gltf-validator@%s failed: %s\n' "$version" \
    "$(printf '%s' "$log" | tail -n 3 | tr '\n' ' ')" > "$target/UNAVAILABLE"
  echo "gltf-validator: $(cat "$target/UNAVAILABLE")" >&2
  exit 0
fi
echo "gltf-validator: installed $version in $target"
