#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs what is missing, builds CoScope and starts it on the simulated drives.
# Extra arguments go to the app (e.g. scripts/run.sh --connect socketcan://can0).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
# Only the two programs (not the tests). In a terminal ninja keeps its progress on one line;
# elsewhere it prints only what goes wrong.
echo "run: building coscope and coscope-cli in build/release (the first build takes a few minutes)..."
quiet=(); [ -t 1 ] || quiet=(-- --quiet)
cmake --build --preset release --target coscope coscope-cli -j"$(nproc)" "${quiet[@]}"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "No display to show the window on; the command line works without one: build/release/app/coscope-cli --help"
  exit 1
fi
if [ $# -eq 0 ]; then set -- --simulate; fi
exec build/release/app/coscope "$@"
