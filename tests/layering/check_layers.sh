#!/usr/bin/env bash
# The layering rules of ARCHITECTURE.md, checked on the sources: no phigs folder imports
# one that imports it back (tsort finds any loop in the folder graph), only phigs/src/window
# includes GLFW, and only phigs/vk (and the window's surface seam) includes Vulkan.
set -euo pipefail
root="$(cd "${1:?usage: check_layers.sh SOURCE_ROOT}" && pwd)"
cd "$root/phigs"
status=0

# Folder edges "from to" from every #include "phigs/<folder>/..." (Phigs.h at the top is "top").
edges=$(find include src -name '*.h' -o -name '*.cpp' | while read -r file; do
    from=$(echo "$file" | sed -E 's#^(include/phigs|src)/([^/]+)/.*#\2#; s#^(include/phigs|src)/[^/]+$#top#')
    { grep -ho '#include "phigs/[A-Za-z]*[/.]' "$file" || true; } | sed -E 's#.*phigs/([A-Za-z]+)[/.]#\1#; s#^Phigs$#top#' |
        while read -r to; do if [ "$to" != "$from" ]; then echo "$from $to"; fi; done
done | sort -u)
if ! echo "$edges" | tsort >/dev/null 2>"${TMPDIR:-/tmp}/tsort.$$"; then
    echo "phigs folders import each other in a loop:"
    grep -v "^tsort: -: input contains a loop:" "${TMPDIR:-/tmp}/tsort.$$" | sed 's/^tsort: /  /'
    status=1
fi
rm -f "${TMPDIR:-/tmp}/tsort.$$"

glfw=$(cd "$root" && grep -rl "GLFW/glfw3.h" phigs apps | grep -v "^phigs/src/window/" || true)
if [ -n "$glfw" ]; then
    echo "GLFW included outside phigs/src/window:"
    echo "$glfw" | sed 's/^/  /'
    status=1
fi
vulkan=$(cd "$root" && grep -rlE "vulkan/vulkan\.h|GLFW_INCLUDE_VULKAN" phigs apps |
    grep -vE "^phigs/(src|include/phigs)/vk/|^phigs/src/window/GlfwWindow.cpp$" || true)
if [ -n "$vulkan" ]; then
    echo "Vulkan included outside phigs/vk:"
    echo "$vulkan" | sed 's/^/  /'
    status=1
fi
if [ "$status" = 0 ]; then echo "layers: $(echo "$edges" | wc -l) folder imports, no loop; GLFW and Vulkan where they belong"; fi
exit "$status"
