#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs what is missing, builds CoScope with warnings as errors and runs the whole test suite.
#   scripts/test.sh [--preset dev|asan] [CTEST-ARGS...]
# --preset asan builds and runs the same suite under AddressSanitizer + UndefinedBehaviorSanitizer.
# COSCOPE_DEBUG_INFO=lines in the environment builds with line tables only (faster; CI uses it).
# COSCOPE_UNITY_BUILD=ON builds the libraries in unity mode, COSCOPE_LINKER=gold links with gold:
# both only make a build from scratch faster (CI); the asan preset always uses both.
# COSCOPE_TEST_AREAS="unit;integration;corpus" builds and runs only those areas (default: all four,
# gui included; CI's ASan pass leaves out gui).
set -euo pipefail
cd "$(dirname "$0")/.."
preset=dev
if [ "${1:-}" = "--preset" ]; then
  preset="${2:?--preset needs dev or asan}"
  shift 2
fi
case "$preset" in dev|asan) ;; *) echo "test.sh: unknown preset '$preset' (dev or asan)" >&2; exit 2 ;; esac
scripts/setup.sh test
cmake --preset "$preset" ${COSCOPE_DEBUG_INFO:+-DCOSCOPE_DEBUG_INFO="$COSCOPE_DEBUG_INFO"} \
  ${COSCOPE_UNITY_BUILD:+-DCMAKE_UNITY_BUILD="$COSCOPE_UNITY_BUILD"} ${COSCOPE_LINKER:+-DCOSCOPE_LINKER="$COSCOPE_LINKER"} \
  -DCOSCOPE_TEST_AREAS="${COSCOPE_TEST_AREAS:-unit;integration;corpus;gui}" >/dev/null
cmake --build --preset "$preset" -j"$(nproc)"
ctest --preset "$preset" "$@"
