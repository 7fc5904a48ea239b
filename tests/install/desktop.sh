#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The installed .desktop entry, AppStream metainfo and MIME types are valid and agree: the
# validators pass, every MIME type CoScope defines is in the entry's MimeType= and the metainfo's
# <provides>, shared-mime-info compiles the types and maps each log extension to them, and the
# newest release in the metainfo is this version.
. "$(dirname "$0")/common.sh"
need desktop-file-validate appstreamcli update-mime-database

desktop=$prefix/share/applications/$app_id.desktop
metainfo=$prefix/share/metainfo/$app_id.metainfo.xml
mime=$prefix/share/mime/packages/$app_id.xml
check "desktop-file-validate $desktop" desktop-file-validate "$desktop"
check "appstreamcli validate --no-net $metainfo" appstreamcli validate --no-net "$metainfo"

grep -q "^Exec=coscope %f$" "$desktop" || fail "Exec= does not start coscope with a file"
grep -q "^Icon=$app_id$" "$desktop" || fail "Icon= is not $app_id"
[ -f "$prefix/share/icons/hicolor/scalable/apps/$app_id.svg" ] || fail "no icon named like Icon="
mimetypes=$(sed -n 's/^MimeType=//p' "$desktop")
types=$(grep -o '<mime-type type="[^"]*"' "$mime" | cut -d'"' -f2)
[ -n "$types" ] || fail "no MIME types in $mime"
for t in $types; do
  [[ ";$mimetypes" == *";$t;"* ]] || fail "MIME type $t is not in the .desktop MimeType=$mimetypes"
  grep -q "<mediatype>$t</mediatype>" "$metainfo" || fail "MIME type $t is not in the metainfo <provides>"
done
echo "ok: .desktop and metainfo list the MIME types: $(echo $types)"

# Compile the MIME database as the system would (shared-mime-info) and look up each extension.
db=$COSCOPE_WORK_DIR/mime-db
rm -rf "$db" && mkdir -p "$db/packages" && cp "$mime" "$db/packages/"
check "update-mime-database accepts the types" update-mime-database "$db"
for pair in trc:text/x-peak-trc asc:text/x-vector-asc blf:application/x-vector-blf \
            pcapng:application/x-pcapng pcap:application/vnd.tcpdump.pcap; do
  ext=${pair%%:*} type=${pair#*:}
  grep -q "^[0-9]*:$type:\*\.$ext$" "$db/globs2" || fail "*.$ext does not map to $type"
done
grep -q "candump-\*\.log" "$db/globs2" || fail "candump-*.log is not recognised"
[ -s "$db/magic" ] || fail "no magic compiled"
echo "ok: log extensions map to CoScope's MIME types"

newest=$(grep -o '<release version="[^"]*"' "$metainfo" | head -1 | cut -d'"' -f2)
[ "$newest" = "$version" ] || fail "newest metainfo release is '$newest', the project is $version: add a <release> to resources/desktop/coscope.metainfo.xml.in"
grep -q "<image[^>]*>https://[^<]*</image>" "$metainfo" || fail "the metainfo has no screenshot"
echo "ok: metainfo release $newest and screenshot"
