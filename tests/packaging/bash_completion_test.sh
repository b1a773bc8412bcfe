#!/usr/bin/env bash
# The bash completion offers ydscope-cli's commands and a command's options, read from --help.
#   bash_completion_test.sh COMPLETION_FILE YDSCOPE_CLI
set -euo pipefail
source "$1"
cli=$2
fail() { echo "bash completion: $*" >&2; exit 1; }

COMP_WORDS=("$cli" "sc"); COMP_CWORD=1
_ydscope_cli
[ "${COMPREPLY[*]}" = "scan" ] || fail "'sc' completed to '${COMPREPLY[*]}', not 'scan'"

COMP_WORDS=("$cli" "decode" "--fo"); COMP_CWORD=2
_ydscope_cli
[ "${COMPREPLY[*]}" = "--force --format" ] || fail "'decode --fo' completed to '${COMPREPLY[*]}', not '--force --format'"

COMP_WORDS=("$cli" "decode" "--form"); COMP_CWORD=2
_ydscope_cli
[ "${COMPREPLY[*]}" = "--format" ] || fail "'decode --form' completed to '${COMPREPLY[*]}', not '--format'"

COMP_WORDS=("$cli" "scan" "--model" "T"); COMP_CWORD=3
_ydscope_cli
[ "${COMPREPLY[*]}" = "TG15 TG30 TG50" ] || fail "'--model T' completed to '${COMPREPLY[*]}'"

COMP_WORDS=("$cli" "help" "rep"); COMP_CWORD=2
_ydscope_cli
[ "${COMPREPLY[*]}" = "replay" ] || fail "'help rep' completed to '${COMPREPLY[*]}', not 'replay'"
echo "bash completion: ok"
