#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `coscope --version` and `coscope-cli --version` print the version and the source revision:
# in a git checkout the commit the build came from, in a source archive the commit `git archive`
# stamped into cmake/archive-revision.txt, else "unknown".
. "$(dirname "$0")/common.sh"

expected_commit=""
if command -v git >/dev/null && git -C "$COSCOPE_SOURCE_DIR" rev-parse --git-dir >/dev/null 2>&1; then
  expected_commit=$(git -C "$COSCOPE_SOURCE_DIR" rev-parse HEAD)
fi
for program in coscope coscope-cli; do
  out=$("$prefix/bin/$program" --version)
  [[ $out =~ ^$program\ ${version//./\\.}\ \(revision\ ([^ ]+)\)$ ]] || fail "$program --version says '$out'"
  revision=${BASH_REMATCH[1]}
  if [ -n "$expected_commit" ]; then
    # git describe: TAG, TAG-N-gHASH or HASH, each maybe with -dirty.
    described=${revision%-dirty}
    commit=$(git -C "$COSCOPE_SOURCE_DIR" rev-parse --verify -q "${described##*-g}^{commit}" ||
             git -C "$COSCOPE_SOURCE_DIR" rev-parse --verify -q "$described^{commit}" || true)
    [ "$commit" = "$expected_commit" ] ||
      fail "$program --version names revision '$revision', the checkout is at $expected_commit (rebuild?)"
  fi
  echo "ok: $out"
done

# Outside a git checkout (a source archive), the stamp or "unknown".
tree=$COSCOPE_WORK_DIR/archive-tree
revision_of_tree() {
  rm -f "$tree/out.h"
  "${COSCOPE_CMAKE:-cmake}" -DSOURCE_DIR="$tree" -DGIT_EXECUTABLE=git -DOUTPUT="$tree/out.h" \
    -P "$COSCOPE_SOURCE_DIR/cmake/WriteRevision.cmake"
  sed -n 's/^#define COSCOPE_REVISION "\(.*\)"$/\1/p' "$tree/out.h"
}
rm -rf "$tree" && mkdir -p "$tree/cmake"
cp "$COSCOPE_SOURCE_DIR/cmake/archive-revision.txt" "$tree/cmake/"
if grep -q '^\$Format' "$tree/cmake/archive-revision.txt"; then
  [ "$(revision_of_tree)" = unknown ] || fail "an unstamped source tree does not say 'unknown'"
fi
sed -i '1s/.*/1a2b3c4d5e6f/' "$tree/cmake/archive-revision.txt"
[ "$(revision_of_tree)" = 1a2b3c4d5e6f ] || fail "a stamped source archive does not give its commit"
echo "ok: source archives: stamp or unknown"
