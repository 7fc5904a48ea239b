#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds the libFuzzer targets (clang, ASan+UBSan) and runs each for SECONDS (default 300) from
# its seed corpus in tests/fuzz/corpus/<target>/. Usage: scripts/fuzz.sh [SECONDS] [NAME-FILTER]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh test
seconds="${1:-300}"
filter="${2:-}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j"$(nproc)"
status=0
for f in build/fuzz/tests/fuzz/fuzz_*; do
  [ -x "$f" ] || continue
  name="$(basename "$f")"
  case "$name" in *"$filter"*) ;; *) continue ;; esac
  seeds="tests/fuzz/corpus/$name"
  work="build/fuzz/corpus/$name"
  mkdir -p "$work"
  echo "== $name for ${seconds}s"
  if ! "$f" -max_total_time="$seconds" -print_final_stats=1 "$work" $( [ -d "$seeds" ] && echo "$seeds" ); then
    echo "$name: FAILED (crash input saved in the current folder)"
    status=1
  fi
done
exit $status
