#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds and runs the benchmarks in tests/bench (release build), each printing its own figures
# and the ratio against its peer and the DESIGN.md budget. Usage: scripts/bench.sh [NAME-FILTER]
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh test
cmake -S . -B build/bench -G Ninja -DCMAKE_BUILD_TYPE=Release -DCOSCOPE_BENCH=ON >/dev/null
cmake --build build/bench -j"$(nproc)"
filter="${1:-}"
for b in build/bench/tests/bench/bench_*; do
  [ -x "$b" ] || continue
  case "$(basename "$b")" in *"$filter"*) ;; *) continue ;; esac
  echo "== $(basename "$b")"
  "$b"
done
