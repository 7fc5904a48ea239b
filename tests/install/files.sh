#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `cmake --install` puts exactly these files in the prefix (GNUInstallDirs layout), the programs
# run from there, and each hicolor PNG has the size of its folder.
. "$(dirname "$0")/common.sh"
need file

expected=(
  bin/coscope
  bin/coscope-cli
  "share/applications/$app_id.desktop"
  share/bash-completion/completions/coscope
  share/bash-completion/completions/coscope-cli
  share/doc/coscope/LICENSE
  share/doc/coscope/README.md
  share/doc/coscope/resources/README.md
  "share/metainfo/$app_id.metainfo.xml"
  "share/mime/packages/$app_id.xml"
  "share/icons/hicolor/scalable/apps/$app_id.svg"
)
for size in 16 24 32 48 64 128 256; do expected+=("share/icons/hicolor/${size}x$size/apps/$app_id.png"); done
if grep -q '^HELP2MAN_EXECUTABLE:FILEPATH=/' "$COSCOPE_BUILD_DIR/CMakeCache.txt"; then
  expected+=(share/man/man1/coscope.1 share/man/man1/coscope-cli.1)
else
  echo "note: built without help2man, so without man pages"
fi

want=$(printf '%s\n' "${expected[@]}" | sort)
have=$(cd "$prefix" && find . -type f -o -type l | sed 's|^\./||' | sort)
if [ "$want" != "$have" ]; then
  diff <(echo "$want") <(echo "$have") >&2 || true
  fail "installed files differ from the expected list (< missing, > unexpected)"
fi
echo "ok: ${#expected[@]} files, as expected"

for program in coscope coscope-cli; do
  [ -x "$prefix/bin/$program" ] || fail "bin/$program is not executable"
  out=$("$prefix/bin/$program" --version) || fail "$program --version failed"
  [[ $out == "$program $version "* ]] || fail "installed $program --version says '$out'"
done
echo "ok: installed programs run"

for png in "$prefix"/share/icons/hicolor/*/apps/*.png; do
  size=$(basename "$(dirname "$(dirname "$png")")")   # 48x48
  info=$(file -b "$png")
  [[ $info == "PNG image data, ${size/x/ x },"* ]] || fail "$png is not a ${size} PNG: $info"
done
echo "ok: icon sizes"
grep -q '<svg' "$prefix/share/icons/hicolor/scalable/apps/$app_id.svg" || fail "the scalable icon is not an SVG"
