#!/usr/bin/env bash
# downstream.sh [BUILD_DIR]: the toolkit as a user outside its tree gets it. Installs the build
# (default: build/, already built) into a temporary prefix, then configures and builds the
# project examples/downstream against it with find_package(phigs CONFIG) alone, and runs its C++
# and C programs; every installed header is compiled on its own too, and the C program is built
# once more through pkg-config (phigs.pc); the installed acsynt reads its installed data.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
echo "downstream: installed $(find "$prefix" -type f | wc -l) files into a temporary prefix"

# One translation unit per installed header would be slow; one that includes them all checks that
# each is installed and that the targets' usage requirements reach everything they need.
mkdir -p "$work/consumer"
(cd "$prefix/include" && find phigs geom -name '*.h' | sort | sed 's/.*/#include <&>/'
 echo 'int main() { return 0; }') > "$work/consumer/all_headers.cpp"

# The consumer sees only the prefix: no CMAKE_CXX_STANDARD, no path into this tree.
cmake -S "$root/examples/downstream" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" -j"$(nproc)"
"$work/consumer/consumer" "$work/consumer/picture.png"
LD_LIBRARY_PATH="$prefix/lib" "$work/consumer/consumer_c"

# C through pkg-config: cc prog.c $(pkg-config --cflags --libs phigs).
pc_dir=$(dirname "$(find "$prefix" -name phigs.pc)")
flags=$(PKG_CONFIG_PATH="$pc_dir" pkg-config --cflags --libs phigs)
# shellcheck disable=SC2086
cc -std=c11 -Wall -Wextra -Werror -pedantic "$root/examples/downstream/consumer.c" $flags \
    -Wl,-rpath,"$prefix/lib" -o "$work/consumer_pc"
"$work/consumer_pc"

# The installed acsynt finds its shipped data in the prefix (share/acsynt/data), not the source
# tree: a model there under a name the source tree lacks is read and exported.
if [ -x "$prefix/bin/acsynt" ]; then
    cp "$prefix/share/acsynt/data/fighter.acm" "$prefix/share/acsynt/data/installed_only.acm"
    (cd "$work" && "$prefix/bin/acsynt" --export "$work/installed.step" installed_only.acm > "$work/acsynt.log") ||
        { cat "$work/acsynt.log"; exit 1; }
    test -s "$work/installed.step"
fi
echo "downstream: ok"
