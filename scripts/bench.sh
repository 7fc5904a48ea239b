#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds and runs the benchmarks in tests/bench (release build), each printing its own figures
# and the ratio against its peer and the DESIGN.md budget, then a summary table: every
# `BENCH name figure unit peer kind ratio` line a benchmark printed, and for benchmarks without
# such lines the budget_ratio / ratio_vs_* counters of their Google Benchmark rows.
# Usage: scripts/bench.sh [NAME-FILTER]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh test
cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOSCOPE_BENCH=ON >/dev/null
cmake --build build/bench -j"$(nproc)"
# The build's files on the disk before anything is timed: the kernel writing them back during a
# benchmark takes CPU from it (seen as a 1.5x slower tshark right after a build).
sync
filter="${1:-}"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
for b in build/bench/tests/bench/bench_*; do
  [ -f "$b" ] && [ -x "$b" ] || continue  # not the bench_*_autogen directories
  case "$(basename "$b")" in *"$filter"*) ;; *) continue ;; esac
  echo "== $(basename "$b")" | tee -a "$log"
  "$b" | tee -a "$log"
done
echo
echo "== summary (ratio >= 1 meets the budget or beats the peer; machine load: $(cut -d' ' -f1-3 /proc/loadavg))"
awk '
  NR == FNR { if ($1 == "==") b = $2; else if ($1 == "BENCH") hasBench[b] = 1; next }
  /^== bench_/ { bench = $2; next }
  /^BENCH / {
    printf "%-44s %12s %-7s %12s %-16s %8sx\n", $2, $3, $4, $5, $6, $7; next
  }
  /^BM_/ && !hasBench[bench] {
    for (i = 1; i <= NF; i++) if ($i ~ /^(budget_ratio|ratio_vs_[a-z_]+)=/) {
      split($i, kv, "="); printf "%-44s %12s %-7s %12s %-16s %8.2fx\n", bench "/" $1, "-", "", "-", kv[1], kv[2]
    }
  }' "$log" "$log" | { printf "%-44s %12s %-7s %12s %-16s %9s\n" benchmark figure unit peer/budget kind ratio; cat; }
