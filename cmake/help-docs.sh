#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Makes a program's man page and bash completion from its own --help, so neither can drift from
# the code. For coscope-cli it also reads every verb's --help (the verbs are the lines under
# "Verbs:"). Usage: help-docs.sh PROGRAM OUTDIR SOURCE_DIR [HELP2MAN]
#   OUTDIR/completions/NAME   bash completion (data from the help + cmake/completion.bash.in)
#   OUTDIR/man/NAME.1         man page (help2man, with docs/man/NAME.h2m and a VERBS section);
#                             skipped when HELP2MAN is empty.
set -euo pipefail
program=$1 outdir=$2 srcdir=$3 help2man=${4:-}
name=$(basename "$program")
fn=_$(printf '%s' "$name" | tr -c 'a-zA-Z0-9\n' '_')   # coscope-cli -> _coscope_cli
work=$outdir/help/$name
mkdir -p "$work" "$outdir/completions" "$outdir/man"
rm -f "$work"/verb-*.txt

# Run the program without touching the user's home, display or leak checker.
export XDG_DATA_HOME=$work/xdg-data XDG_CONFIG_HOME=$work/xdg-config XDG_RUNTIME_DIR=$work/xdg-runtime
export QT_QPA_PLATFORM=offscreen ASAN_OPTIONS=detect_leaks=0 COSCOPE_LOG_LEVEL=off
mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
"$program" --help >"$work/main.txt"

# Verb names: "  sdo read      Read an object..." -> "sdo read" (the name ends at two spaces).
mapfile -t verbs < <(awk '/^Verbs:/ {on = 1; next} on && /^$/ {exit} on && /^  [^ ]/ {
  sub(/^  /, ""); sub(/  .*/, ""); print }' "$work/main.txt")
i=0
for verb in "${verbs[@]}"; do
  # shellcheck disable=SC2086  # a two-word verb is two arguments
  "$program" $verb --help >"$work/verb-$(printf '%03d' $i).txt"
  i=$((i + 1))
done

# Options of one help text: "  -h, --help   ..." and "  --dict <FILE>  ..." (exactly two spaces
# before the dash; deeper lines continue a description). Prints "names|valued names".
options_of() {
  awk '/^  -/ { spec = substr($0, 3); sub(/  .*/, "", spec)
    n = split(spec, forms, /, /)
    for (k = 1; k <= n; k++) { split(forms[k], w, / /); names = names " " w[1]; if (w[2] != "") valued = valued " " w[1] } }
    END { sub(/^ /, "", names); print names "|" valued " " }' "$1"
}

# --- bash completion -------------------------------------------------------------------------
{
  echo "# bash completion for $name, generated from its --help by cmake/help-docs.sh: do not edit."
  IFS='|' read -r names valued < <(options_of "$work/main.txt")
  echo "${fn}_global_options='$names'"
  echo "${fn}_global_valued='$valued'"
  printf '%s_verbs=(' "$fn"; for v in "${verbs[@]+"${verbs[@]}"}"; do printf " '%s'" "$v"; done; echo ' )'
  heads=$(for v in "${verbs[@]+"${verbs[@]}"}"; do echo "${v%% *}"; done | sort -u | tr '\n' ' ')
  echo "${fn}_verb_heads='${heads% }'"
  echo "${fn}_verb_options() {  # sets options and valued of the caller for verb \$1"
  echo '  case "$1" in'
  i=0
  for verb in "${verbs[@]+"${verbs[@]}"}"; do
    IFS='|' read -r names valued < <(options_of "$work/verb-$(printf '%03d' $i).txt")
    echo "    '$verb') options='$names'; valued='$valued' ;;"
    i=$((i + 1))
  done
  echo "    *) options=''; valued=' ' ;;"
  echo '  esac'
  echo '}'
  sed -e "s/@FN@/$fn/g" -e "s/@PROGRAM@/$name/g" "$srcdir/cmake/completion.bash.in" | grep -v '^# SPDX\|^#@'
} >"$outdir/completions/$name.tmp"
mv "$outdir/completions/$name.tmp" "$outdir/completions/$name"

# --- man page ----------------------------------------------------------------------------------
[ -n "$help2man" ] || exit 0
include=$work/$name.h2m
cp "$srcdir/docs/man/$name.h2m" "$include"
if [ ${#verbs[@]} -gt 0 ]; then
  echo '[VERBS]' >>"$include"
  i=0
  for verb in "${verbs[@]}"; do
    # Usage line, description, then "Options:"/"Arguments:" lists as tagged paragraphs.
    awk -v verb="$verb" -v prog="$name" '
      function esc(s) { gsub(/\\/, "\\e", s); gsub(/-/, "\\-", s); sub(/^[.'"'"']/, "\\\\&&", s); return s }
      function flush() { if (term != "") { print ".TP"; print term; print esc(desc) } term = ""; desc = "" }
      BEGIN { print ".SS \"" verb "\"" }
      /^Usage: / { line = $0; sub(/^Usage: [^ ]+ /, "", line); if (index(line, verb " ") == 1) line = substr(line, length(verb) + 2)
                   print ".PP"; print "\\fB" esc(prog " " verb) "\\fR " esc(line); next }
      /^  [^ ]/ { flush(); para = 0; spec = substr($0, 3); desc = spec; sub(/  .*/, "", spec); sub(/^[^ ]+( [^ ]+)*  +/, "", desc)
                  if (desc == spec) desc = ""
                  n = split(spec, forms, /, /); term = ""
                  for (k = 1; k <= n; k++) { w = forms[k]; v = ""; if (index(w, " ")) { v = substr(w, index(w, " ")); w = substr(w, 1, index(w, " ") - 1) }
                    term = term (k > 1 ? ", " : "") "\\fB" esc(w) "\\fR" esc(v) }
                  next }
      /^   / { line = $0; sub(/^ +/, "", line); desc = desc " " line; next }
      /^$/ { flush(); para = 0; next }
      # Text lines: a line that ends a sentence keeps its break, others flow on.
      { flush(); if (!para) print ".PP"; else if (last ~ /[.:;)]$/) print ".br"
        print esc($0); para = 1; last = $0 }
      END { flush() }' "$work/verb-$(printf '%03d' $i).txt" >>"$include"
    i=$((i + 1))
  done
fi
case $name in
  coscope-cli) summary="CANopen bus analyzer and servo-drive commissioning tool, command line" ;;
  *) summary="CANopen bus analyzer and servo-drive commissioning tool" ;;
esac
version=$("$program" --version | awk '{print $2; exit}')
"$help2man" --no-info --section=1 --name="$summary" --version-string="$version" \
  --manual="User Commands" --source="CoScope $version" --include="$include" \
  --output="$outdir/man/$name.1.tmp" "$program"
mv "$outdir/man/$name.1.tmp" "$outdir/man/$name.1"
