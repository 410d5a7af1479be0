#!/usr/bin/env bash
# The documentation stands on its own: no tracked file points at material outside the tree (a
# numbered source document, a note about one, an issue, a design page beside the clone) instead
# of citing the published work (author, title, year) or saying the thing itself; and every
# README is a screen or two (at most 150 lines), reference tables going to files of their own.
# Usage: check_docs.sh SOURCE_DIR
set -uo pipefail
root=${1:-$(dirname "$0")/../..}
cd "$root" || exit 2

# Tracked files (git), else every file but build trees and VCS folders.
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard)
else
  mapfile -t files < <(find . -type f -not -path './build*' -not -path './.git/*' | sed 's|^\./||')
fi

# References to material outside the tree. ("seed" alone is a random or fuzzing seed, and
# "issues" a list of problems: both stay.)
patterns=(
  '\bseeds? ?-?0[0-9]{2}'                 # "seed 004", "seed-002", "seeds 000"
  "\bthe seed's"                           # "the seed's menu"
  '\bseed (§|table|fig|ch\b|chapter)'      # "seed §7.5", "seed Table 2"
  '\bthe seed (draws|shows|uses|says)'
  '\bnotes? 0[0-9]{2}'                     # "note 000"
  'notes/0[0-9]{2}'
  '\bthe issue\b'
  "\bissue's\b"
  '\bissues? #?[0-9]+'                     # "issue 17"
  '\.\./shared/|\.\./seeds/|\bDESIGN\.md'
)
self=tests/docs/check_docs.sh
checked=()
readmes=()
for file in "${files[@]}"; do
  [ -f "$file" ] && [ "$file" != "$self" ] || continue
  checked+=("$file")
  case ${file##*/} in README.md | README) readmes+=("$file") ;; esac
done
status=0
# One grep over every file and pattern: file:line:text for each hit.
if hits=$(printf '%s\n' "${patterns[@]}" | grep -I -n -H -i -E -f - -- "${checked[@]}"); then
  while IFS= read -r hit; do
    echo "$hit  <- a reference outside the tree: cite the published work, or say it"
  done <<<"$hits"
  status=1
fi
# The same references broken over two lines ("... as in note" / "/// 000 ...", an issue's
# number likewise): the number
# opens the next line, after its comment marker.
hits=$(awk 'FNR == 1 { prev = "" }
    { line = $0; sub(/^[ \t]*(\/\/\/?|#+|\*|--)?[ \t]*/, "", line)
      end = tolower(prev)
      if ((end ~ /(^|[^a-z])(seeds?|notes?)[ \t]*-?$/ && line ~ /^0[0-9][0-9]([^0-9]|$)/) ||
          (end ~ /(^|[^a-z])issues?[ \t]*$/ && line ~ /^#?[0-9]+/))
          print FILENAME ":" FNR ":" $0
      prev = $0 }' "${checked[@]}")
if [ -n "$hits" ]; then
  while IFS= read -r hit; do
    echo "$hit  <- a reference outside the tree (over two lines): cite the published work, or say it"
  done <<<"$hits"
  status=1
fi
if ((${#readmes[@]})); then
  while read -r lines file; do
    [ "$file" = total ] && continue
    if ((lines > 150)); then
      echo "$file: $lines lines; a README is at most 150 (move reference tables to a file of their own)"
      status=1
    fi
  done < <(wc -l -- "${readmes[@]}")
fi
((status == 0)) && echo "docs: ${#checked[@]} files and ${#readmes[@]} READMEs checked"
exit $status
