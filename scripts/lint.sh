#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Static analysis: clang-tidy 14 with the checks in .clang-tidy over the program's code (app/,
# core/, eds/, dissectors/; not the tests). Prints each warning once and exits 1 if there is any.
# Run it before each stop (issue 38): about 15-20 minutes on 2 idle cores.
#   scripts/lint.sh            every source
#   scripts/lint.sh REGEX      only the unity batches whose path matches REGEX (e.g. core/)
#   scripts/lint.sh --fix [REGEX]  also apply clang-tidy's fixes (each once, however many batches
#                              report it: clang-apply-replacements), then format the tree
# The lint build (build/lint) is configured, never built: a unity build with 16 sources per batch,
# so the Qt and standard headers are parsed and checked once per batch instead of once per file,
# which makes the run about eight times shorter.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh test
cmake -S . -B build/lint -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCOSCOPE_TESTS=OFF -DCOSCOPE_BENCH=OFF \
  -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
# The one generated header the sources include (the build's revision).
cmake --build build/lint --target coscope_revision >/dev/null
fix=0
if [ "${1:-}" = "--fix" ]; then
  fix=1
  shift
fi
filter="${1:-}"
mapfile -t batches < <(python3 -c '
import json, sys
for e in json.load(open("build/lint/compile_commands.json")):
    if "/Unity/unity_" in e["file"]:
        print(e["file"])' | grep -e "$filter" || true)
[ ${#batches[@]} -gt 0 ] || { echo "lint: no unity batch matches '$filter'"; exit 2; }
# Unity batches name their sources in comments only; say which directories a filter picked.
echo "lint: ${#batches[@]} batches"
out="build/lint/clang-tidy.log"
if [ "$fix" = 1 ]; then
  fixes="build/lint/fixes"
  rm -rf "$fixes"
  mkdir -p "$fixes"
  # One YAML of fixes a batch; clang-apply-replacements merges them and drops the duplicates
  # (a header's fix is exported by every batch that includes it).
  printf '%s\0' "${batches[@]}" | xargs -0 -n 1 -P "$(nproc)" sh -c \
    'clang-tidy-14 -p build/lint --quiet --export-fixes="$0/$(echo "$1" | md5sum | cut -c1-12).yaml" "$1"' \
    "$fixes" >"$out" 2>/dev/null || true
  clang-apply-replacements-14 --remove-change-desc-files "$fixes"
  scripts/format.sh
  echo "lint: fixes applied; run scripts/lint.sh again for what is left"
  exit 0
fi
printf '%s\0' "${batches[@]}" | xargs -0 -n 1 -P "$(nproc)" clang-tidy-14 -p build/lint --quiet >"$out" 2>/dev/null || true
# A header seen from several batches reports its warning in each: print every warning once.
warnings="$(grep -E '^/.*: (warning|error): ' "$out" | sort -u || true)"
if [ -n "$warnings" ]; then
  echo "$warnings"
  echo "lint: $(echo "$warnings" | wc -l) warnings (full output in $out)"
  exit 1
fi
echo "lint: 0 warnings"
