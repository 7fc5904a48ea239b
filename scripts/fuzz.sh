#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the libFuzzer targets alone (clang, ASan+UBSan; not the rest of the tree) and runs each
# for SECONDS (default 300) from its seed corpus in tests/fuzz/corpus/<target>/; what a run finds
# new stays in build/fuzz/corpus/<target>/. Usage: scripts/fuzz.sh [SECONDS] [NAME-FILTER]
# CI (.ci/run) runs every target for 10 s so fuzzing cannot rot unseen.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh test
seconds="${1:-300}"
filter="${2:-}"
cmake --preset fuzz ${COSCOPE_DEBUG_INFO:+-DCOSCOPE_DEBUG_INFO="$COSCOPE_DEBUG_INFO"} >/dev/null
targets=()
for src in tests/fuzz/fuzz_*.cpp; do
  name="$(basename "$src" .cpp)"
  case "$name" in *"$filter"*) targets+=("$name") ;; esac
done
[ ${#targets[@]} -gt 0 ] || { echo "no fuzz target matches '$filter'"; exit 2; }
cmake --build --preset fuzz -j"$(nproc)" --target "${targets[@]}"
status=0
for name in "${targets[@]}"; do
  f="build/fuzz/tests/fuzz/$name"
  seeds="tests/fuzz/corpus/$name"
  work="build/fuzz/corpus/$name"
  mkdir -p "$work"
  echo "== $name for ${seconds}s"
  mkdir -p build/fuzz/crashes
  if ! "$f" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix=build/fuzz/crashes/"$name"- "$work" $( [ -d "$seeds" ] && echo "$seeds" ); then
    echo "$name: FAILED (the input is in build/fuzz/crashes/)"
    status=1
  fi
done
exit $status
