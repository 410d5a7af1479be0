#!/usr/bin/env bash
# Every Catch2 test file keeps its contents in a namespace named after the file, so unity builds
# (CMAKE_UNITY_BUILD, used by CI) can batch test files whose helpers share short names.
set -euo pipefail
root="$(cd "${1:?usage: check_test_namespaces.sh SOURCE_ROOT}" && pwd)"
cd "$root/tests"
status=0
for file in */*.cpp; do
    case "$file" in support/* | fuzz/*) continue ;; esac
    name=$(basename "$file" .cpp)
    if ! grep -q "^namespace $name {" "$file" || ! grep -q "^}  // namespace $name\$" "$file"; then
        echo "tests/$file: wrap its contents in 'namespace $name { ... }  // namespace $name'"
        status=1
    fi
done
exit $status
