#!/bin/bash
# check_exports.sh LIBRARY HEADER: the dynamic symbols LIBRARY defines are exactly the
# functions HEADER declares (no C++ name, no missing name).
set -euo pipefail
library=$1 header=$2
declared=$(grep -oE '^[A-Za-z_][A-Za-z0-9_ ]*[ *]p[a-z0-9_]+\(' "$header" | grep -oE 'p[a-z0-9_]+\($' | tr -d '(' | sort -u)
exported=$(nm -D --defined-only "$library" | awk '$2 == "T" { print $3 }' | sort -u)
status=0
missing=$(comm -23 <(echo "$declared") <(echo "$exported"))
extra=$(comm -13 <(echo "$declared") <(echo "$exported"))
if [ -n "$missing" ]; then echo "declared in phigs.h, not exported:"; echo "$missing"; status=1; fi
if [ -n "$extra" ]; then echo "exported, not in phigs.h:"; echo "$extra"; status=1; fi
other=$(nm -D --defined-only "$library" | awk '$2 != "T" && $2 != "A" { print }')
if [ -n "$other" ]; then echo "other defined symbols:"; echo "$other"; status=1; fi
echo "$(echo "$declared" | wc -l) names declared, $(echo "$exported" | wc -l) exported"
exit $status
