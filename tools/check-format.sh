#!/usr/bin/env bash
# Checks (or with --fix, applies) clang-format on Relief's C++ sources.
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t files < <(git ls-files -co --exclude-standard -- '*.cpp' '*.h')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
if ! clang-format --dry-run --Werror "${files[@]}" 2>/tmp/relief-format.log; then
  grep -m 20 'error:' /tmp/relief-format.log >&2 || true
  echo "check-format: files differ from .clang-format; run 'make format'" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files formatted"
