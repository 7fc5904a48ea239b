#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# `man -l` renders both installed man pages without warnings; coscope-cli(1) has a section for
# every verb the CLI lists, naming each of that verb's options, and coscope(1) every app option.
. "$(dirname "$0")/common.sh"
need man
man1=$prefix/share/man/man1
[ -f "$man1/coscope-cli.1" ] || skip "no man pages installed (built without help2man)"
export MANWIDTH=200 LC_ALL=C.UTF-8

render() {  # page -> plain text; fails on any groff/man warning
  local text warnings
  warnings=$(mktemp)
  text=$(man --warnings -l "$1" 2>"$warnings") || fail "man -l $1 failed: $(cat "$warnings")"
  [ ! -s "$warnings" ] || fail "man -l $1 warns: $(cat "$warnings")"
  rm -f "$warnings"
  # groff may print minus signs as U+2212; compare with plain hyphens.
  printf '%s\n' "$text" | sed 's/\xe2\x88\x92/-/g; s/\xe2\x80\x90/-/g'
}
long_options() { "$@" --help | grep -o '^  -[^ ]*\(, --[^ ]*\)\?' | grep -o -- '--[a-z0-9-]*' || true; }

cli=$(render "$man1/coscope-cli.1")
grep -q '^NAME' <<<"$cli" || fail "coscope-cli(1) has no NAME section"
grep -q '^VERBS' <<<"$cli" || fail "coscope-cli(1) has no VERBS section"
count=0
while IFS= read -r verb; do
  # The verb's subsection runs from its heading to the next heading.
  section=$(awk -v h="   $verb" '$0 == h {on = 1; next} on && /^   [^ ]/ {exit} on && /^[A-Z]/ {exit} on' <<<"$cli")
  [ -n "$section" ] || fail "coscope-cli(1) has no section for verb '$verb'"
  # shellcheck disable=SC2086
  for option in $(long_options "$prefix/bin/coscope-cli" $verb); do
    grep -q -- "$option" <<<"$section" || fail "coscope-cli(1) does not name $option under '$verb'"
  done
  count=$((count + 1))
done < <(cli_verbs "$prefix/bin/coscope-cli")
[ "$count" -gt 10 ] || fail "only $count verbs found in coscope-cli --help"
echo "ok: coscope-cli(1) covers $count verbs and their options"
for option in $(long_options "$prefix/bin/coscope-cli"); do
  grep -q -- "$option" <<<"$cli" || fail "coscope-cli(1) does not name the global option $option"
done

gui=$(render "$man1/coscope.1")
for option in $(long_options "$prefix/bin/coscope"); do
  grep -q -- "$option" <<<"$gui" || fail "coscope(1) does not name $option"
done
grep -q "coscope-cli(1)" <<<"$gui" || fail "coscope(1) does not refer to coscope-cli(1)"
echo "ok: coscope(1) names every option"
