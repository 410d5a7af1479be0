#!/bin/bash
# run_example.sh [-e REGEX]... -- PROGRAM [ARGS...]: runs an example, shows its output, and
# fails when it exits non-zero or when a REGEX (extended, each on its own) matches no line of
# its standard output. The examples' ctest tests (label examples) use it.
set -uo pipefail
patterns=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    [ "$1" = "-e" ] || { echo "run_example.sh: expected -e REGEX or --, got '$1'" >&2; exit 2; }
    patterns+=("$2")
    shift 2
done
shift
output=$("$@")
status=$?
printf '%s\n' "$output"
[ $status -eq 0 ] || { echo "run_example.sh: $1 exited with status $status" >&2; exit 1; }
for pattern in "${patterns[@]}"; do
    grep -Eq -- "$pattern" <<< "$output" || { echo "run_example.sh: no line matches '$pattern'" >&2; exit 1; }
done
