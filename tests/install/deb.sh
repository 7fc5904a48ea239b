#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# CPack makes coscope_VERSION_ARCH.deb from this build tree: its Depends (dpkg-shlibdeps) name the
# Qt, spdlog and QCustomPlot libraries, it holds the desktop files under /usr, and the unpacked
# coscope-cli runs.
. "$(dirname "$0")/common.sh"
need dpkg-deb dpkg-shlibdeps dpkg file
out=$COSCOPE_WORK_DIR/deb
rm -rf "$out" && mkdir -p "$out"
start=$SECONDS
"${COSCOPE_CPACK:-cpack}" --config "$COSCOPE_BUILD_DIR/CPackConfig.cmake" -B "$out" >"$out/cpack.log" 2>&1 ||
  fail "cpack failed: $(tail -20 "$out/cpack.log")"
deb=$out/coscope_${version}_$(dpkg --print-architecture).deb
[ -f "$deb" ] || fail "no $(basename "$deb"); made: $(ls "$out")"
echo "ok: $(basename "$deb"), $(du -k "$deb" | cut -f1) KiB, in $((SECONDS - start)) s"

[ "$(dpkg-deb -f "$deb" Package)" = coscope ] || fail "Package is not coscope"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "Version is not $version"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libqt6core6 libqt6gui6 libqt6widgets6 libqt6serialbus6 libspdlog libqcustomplot; do
  [[ $depends =~ (^|[ ,])$lib[a-z0-9.-]*( |,|$) ]] || fail "Depends does not name $lib"
done
echo "ok: Depends names Qt, spdlog and QCustomPlot"

root=$out/root
dpkg-deb -x "$deb" "$root"
for f in usr/bin/coscope usr/bin/coscope-cli "usr/share/applications/$app_id.desktop" \
         "usr/share/metainfo/$app_id.metainfo.xml" "usr/share/icons/hicolor/scalable/apps/$app_id.svg" \
         "usr/share/mime/packages/$app_id.xml" usr/share/bash-completion/completions/coscope-cli \
         usr/share/doc/coscope/LICENSE; do
  [ -e "$root/$f" ] || fail "the package has no /$f"
done
file -b "$root/usr/bin/coscope-cli" | grep -q ', stripped' || fail "coscope-cli in the package is not stripped"
got=$("$root/usr/bin/coscope-cli" --version) || fail "the unpacked coscope-cli --version failed"
[[ $got == "coscope-cli $version (revision "*")" ]] || fail "the unpacked coscope-cli --version says '$got'"
echo "ok: unpacked: $got"
rm -rf "$root"
