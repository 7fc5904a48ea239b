# SPDX-License-Identifier: GPL-3.0-or-later
# Sourced by the install tests: strict mode, the tree under test, and skip/fail helpers.
set -euo pipefail
: "${COSCOPE_BUILD_DIR:?}" "${COSCOPE_PREFIX:?}" "${COSCOPE_SOURCE_DIR:?}" "${COSCOPE_VERSION:?}" "${COSCOPE_APP_ID:?}"
prefix=$COSCOPE_PREFIX
app_id=$COSCOPE_APP_ID
version=$COSCOPE_VERSION
export QT_QPA_PLATFORM=offscreen XDG_RUNTIME_DIR=${COSCOPE_WORK_DIR:?}/xdg-runtime
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"

# CTest counts exit status 77 as skipped.
skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }
need() { for tool in "$@"; do command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/setup.sh test)"; done; }
# Prints "ok: what" when the command succeeds, else fails with its output.
check() {
  local what=$1 out; shift
  if out=$("$@" 2>&1); then echo "ok: $what"; else fail "$what: $out"; fi
}
# The verbs coscope-cli lists in its --help ("sdo read", ...), one per line.
cli_verbs() {
  "$1" --help | awk '/^Verbs:/ {on = 1; next} on && /^$/ {exit} on && /^  [^ ]/ {sub(/^  /, ""); sub(/  .*/, ""); print}'
}
