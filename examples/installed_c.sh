#!/bin/bash
# installed_c.sh BUILD_DIR PREFIX SOURCE CC FLAGS [-e REGEX]... -- [ARGS...]: installs libphigs and
# phigs.h under PREFIX, builds the C example SOURCE against them alone (C11, -Werror -pedantic;
# FLAGS: a sanitizer build's options), and runs it through run_example.sh with the REGEXes.
set -euo pipefail
build=$1 prefix=$2 source=$3 cc=$4 flags=$5
shift 5
rm -rf "$prefix"
cmake --install "$build/phigs/c" --prefix "$prefix" > /dev/null
program=$prefix/bin/$(basename "$source" .c)
mkdir -p "$prefix/bin"
# shellcheck disable=SC2086
"$cc" -std=c11 -Wall -Wextra -Werror -pedantic $flags -I"$prefix/include" "$source" \
    -L"$prefix/lib" -lphigs -Wl,-rpath,"$prefix/lib" -o "$program"
patterns=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    patterns+=("$1" "$2")
    shift 2
done
shift
exec bash "$(dirname "$0")/run_example.sh" "${patterns[@]}" -- "$program" "$@"
