#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Formats every tracked C++ file with clang-format 14 and the repository's .clang-format.
#   scripts/format.sh           rewrite the files in place
#   scripts/format.sh --check   change nothing; list the files that are not formatted, exit 1 if any
# CI (.ci/run) runs the check first: it takes seconds.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh test
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${1:-}" = "--check" ]; then
  # One process per 50 files; clang-format names each unformatted file in its diagnostics.
  bad="$(printf '%s\0' "${files[@]}" | xargs -0 -n 50 -P "$(nproc)" clang-format-14 --dry-run 2>&1 \
    | sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: warning: code should be clang-formatted.*/\1/p' | sort -u)"
  if [ -n "$bad" ]; then
    echo "not formatted (run scripts/format.sh):" >&2
    echo "$bad" >&2
    exit 1
  fi
  echo "format: ${#files[@]} files formatted"
else
  printf '%s\0' "${files[@]}" | xargs -0 -n 50 -P "$(nproc)" clang-format-14 -i
fi
