#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The installed bash completion offers what a user expects at <TAB>: driven like bash does it
# (COMP_WORDS/COMP_CWORD, then the function `complete` registered), checking COMPREPLY.
. "$(dirname "$0")/common.sh"
completions=$prefix/share/bash-completion/completions

# The completion files are sourced into this shell, as an interactive bash would.
declare -A function_of
for program in coscope coscope-cli; do
  # shellcheck disable=SC1090
  source "$completions/$program" || fail "sourcing $completions/$program failed"
  spec=$(complete -p "$program") || fail "$completions/$program registers no completion for $program"
  [[ $spec =~ -F\ ([^ ]+) ]] || fail "no completion function in '$spec'"
  function_of[$program]=${BASH_REMATCH[1]}
done

# complete_words PROGRAM WORD...: fills COMPREPLY for the last word, as bash does at <TAB>.
complete_words() {
  COMP_WORDS=("$@") COMP_CWORD=$(($# - 1)) COMP_LINE="$*" COMP_POINT=${#COMP_LINE} COMPREPLY=()
  set +eu  # completion functions run in an interactive shell, without strict mode
  "${function_of[$1]}" "$1" "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD-1]}"
  set -eu
}
offers() {  # offers WORD: COMPREPLY holds WORD
  local w
  for w in "${COMPREPLY[@]}"; do [ "$w" = "$1" ] && return 0; done
  return 1
}
expect() {  # expect "WANTED WORDS" PROGRAM WORD...: COMPREPLY is exactly those words
  local want=$1 w; shift
  complete_words "$@"
  local -a wanted=($want)
  [ ${#COMPREPLY[@]} -eq ${#wanted[@]} ] || fail "'$* <TAB>' offers '${COMPREPLY[*]}', expected '$want'"
  for w in "${wanted[@]}"; do offers "$w" || fail "'$* <TAB>' offers '${COMPREPLY[*]}', expected '$want'"; done
  echo "ok: '$* <TAB>' -> $want"
}

expect "sdo" coscope-cli sd
expect "read write" coscope-cli sdo ""
expect "read" coscope-cli sdo r
expect "--timeout --type" coscope-cli sdo read --t
expect "--dry-run" coscope-cli dcf apply sim : // 1 --dr  # bash splits URLs at ":"
expect "debug" coscope-cli --log-level de
expect "sdo" coscope-cli --log-level info sd
expect "--help --log-level --version" coscope-cli --
expect "" coscope-cli decode --dict ""
expect "--simulate" coscope --sim
expect "--screenshot" coscope --simulate --scr
expect "--connect" coscope capture.trc --con

# Every verb the CLI lists completes from its first word, and its options from "--".
while IFS= read -r verb; do
  head=${verb%% *}
  complete_words coscope-cli "$head"
  offers "$head" || fail "'coscope-cli $head<TAB>' offers '${COMPREPLY[*]}', not $head"
  # shellcheck disable=SC2086
  complete_words coscope-cli $verb --
  offers --help || fail "'coscope-cli $verb --<TAB>' offers '${COMPREPLY[*]}', not the verb's options"
done < <(cli_verbs "$prefix/bin/coscope-cli")
echo "ok: every verb and its options complete"

# bash-completion finds the file by the command's name in XDG_DATA_DIRS (on-demand loading).
loader=/usr/share/bash-completion/bash_completion
if [ -f "$loader" ]; then
  found=$(XDG_DATA_DIRS="$prefix/share" bash --norc --noprofile -c '
    source /usr/share/bash-completion/bash_completion
    _completion_loader coscope-cli >/dev/null 2>&1
    complete -p coscope-cli' 2>&1) || fail "bash-completion does not load coscope-cli's completion: $found"
  echo "ok: bash-completion loads it on demand ($found)"
else
  echo "note: bash-completion not installed; on-demand loading not checked"
fi
