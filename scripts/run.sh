#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs what is missing, builds CoScope and starts it on the simulated drives.
# Extra arguments go to the app (e.g. scripts/run.sh --connect socketcan://can0).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake --preset release >/dev/null
cmake --build --preset release -j"$(nproc)"
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ]; then
  echo "No display to show the window on; the command line works without one: build/release/app/coscope-cli --help"
  exit 1
fi
if [ $# -eq 0 ]; then set -- --simulate; fi
exec build/release/app/coscope "$@"
