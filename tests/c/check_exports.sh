#!/bin/bash
# check_exports.sh LIBRARY HEADER COVERAGE: LIBRARY's soname is libphigs.so.MAJOR, the dynamic
# symbols it defines are exactly the functions HEADER declares (no C++ name, no missing name), and
# COVERAGE (COVERAGE.md) lists those names, 323 of ISO/IEC 9593-4 and 75 of PHIGS PLUS (its last
# table), none of them missing.
set -euo pipefail
library=$1 header=$2 coverage=$3
declared=$(grep -oE '^[A-Za-z_][A-Za-z0-9_ ]*[ *]p[a-z0-9_]+\(' "$header" | grep -oE 'p[a-z0-9_]+\($' | tr -d '(' | sort -u)
exported=$(nm -D --defined-only "$library" | awk '$2 == "T" { print $3 }' | sort -u)
status=0
missing=$(comm -23 <(echo "$declared") <(echo "$exported"))
extra=$(comm -13 <(echo "$declared") <(echo "$exported"))
if [ -n "$missing" ]; then echo "declared in phigs.h, not exported:"; echo "$missing"; status=1; fi
if [ -n "$extra" ]; then echo "exported, not in phigs.h:"; echo "$extra"; status=1; fi
soname=$(objdump -p "$library" | awk '$1 == "SONAME" { print $2 }')
if ! [[ "$soname" =~ ^libphigs\.so\.[0-9]+$ ]]; then echo "soname '$soname', not libphigs.so.MAJOR"; status=1; fi
other=$(nm -D --defined-only "$library" | awk '$2 != "T" && $2 != "A" { print }')
if [ -n "$other" ]; then echo "other defined symbols:"; echo "$other"; status=1; fi
names() { grep -oE '^\| `p[a-z0-9_]+`' | tr -d '|` ' | sort -u; }
plus_at=$(grep -n '^## PHIGS PLUS' "$coverage" | cut -d: -f1)
core=$(head -n "$((plus_at - 1))" "$coverage" | names)
plus=$(tail -n "+$plus_at" "$coverage" | names)
listed=$(printf '%s\n%s\n' "$core" "$plus" | sort -u)
if [ "$(echo "$core" | wc -l)" != 323 ] || [ "$(echo "$plus" | wc -l)" != 75 ]; then
    echo "$coverage lists $(echo "$core" | wc -l) core and $(echo "$plus" | wc -l) PHIGS PLUS names, not 323 and 75"
    status=1
fi
if [ "$listed" != "$declared" ]; then
    echo "listed in $coverage, not declared:"; comm -23 <(echo "$listed") <(echo "$declared")
    echo "declared, not listed in $coverage:"; comm -13 <(echo "$listed") <(echo "$declared")
    status=1
fi
if grep -qiE '^\| `p[a-z0-9_]+` \|.*missing' "$coverage"; then
    echo "$coverage has missing names:"; grep -iE '^\| `p[a-z0-9_]+` \|.*missing' "$coverage"
    status=1
fi
echo "$(echo "$declared" | wc -l) names declared, $(echo "$exported" | wc -l) exported"
exit $status
