#!/bin/bash
# check_installed.sh BUILD_DIR PREFIX SOURCE CC [FLAGS]: installs libphigs and phigs.h under
# PREFIX, then builds SOURCE (with its check.h) as C11 against them alone and runs it. FLAGS: the
# sanitizer options of a sanitizer build.
set -euo pipefail
build=$1 prefix=$2 source=$3 cc=$4 flags=${5:-}
rm -rf "$prefix"
cmake --install "$build/phigs/c" --prefix "$prefix" > /dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$source" "$(dirname "$source")/check.h" "$work/"
# shellcheck disable=SC2086
"$cc" -std=c11 -Wall -Wextra -Werror -pedantic $flags -I"$prefix/include" "$work/$(basename "$source")" \
    -L"$prefix/lib" -lphigs -lm -Wl,-rpath,"$prefix/lib" -o "$work/program"
"$work/program"
