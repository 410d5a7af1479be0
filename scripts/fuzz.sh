#!/usr/bin/env bash
# Runs libFuzzer targets of tests/fuzz (README there) under ASan + UBSan for SECONDS each, after
# building them with clang (PHIGS_FUZZ=ON, PHIGS_SANITIZE=ON). Seeds are the shipped files; the
# corpus grows in $FUZZ_WORK/corpus/TARGET across runs; findings (crash, sanitizer report, leak,
# timeout, out of memory, broken property) go to $FUZZ_WORK/findings/ and make the exit status 1.
#
#   scripts/fuzz.sh TARGET|all SECONDS [libFuzzer options...]     TARGET: crv acm archive script session
#
# Environment: FUZZ_BUILD (build directory, default build-fuzz), FUZZ_WORK (default
# $FUZZ_BUILD/fuzz), FUZZ_JOBS (targets run at once, default 1), FUZZ_MAX_LEN (bytes, default
# 1048576: the readers' limits lie far beyond libFuzzer's own choice), FUZZ_TIMEOUT (seconds per
# input, default 10), FUZZ_RSS_MB (default 2048); FUZZ_SECONDS_<TARGET> and FUZZ_TIMEOUT_<TARGET>
# set one target's time and timeout.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
all_targets=(session crv acm archive script)  # the slowest first: it overlaps the others

if [ $# -lt 2 ] || ! [[ $2 =~ ^[0-9]+$ ]]; then
  echo "usage: scripts/fuzz.sh TARGET|all SECONDS [libFuzzer options...]  (TARGET: ${all_targets[*]})" >&2
  exit 2
fi
if [ "$1" = all ]; then
  targets=("${all_targets[@]}")
elif [[ " ${all_targets[*]} " == *" $1 "* ]]; then
  targets=("$1")
else
  echo "fuzz: unknown target '$1' (known: ${all_targets[*]} all)" >&2
  exit 2
fi
seconds=$2
shift 2
build=$(realpath -m "${FUZZ_BUILD:-build-fuzz}")
work=$(realpath -m "${FUZZ_WORK:-$build/fuzz}")

# A new build directory gets only what the targets need, with line tables only (stack traces
# keep file and line; full debug info is most of the compile time); an existing one (CI's clang
# build, which also builds tests) keeps its settings once it has the targets.
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
    -DPHIGS_BUILD_TESTS=OFF -DPHIGS_BUILD_BENCH=OFF -DPHIGS_FUZZ=ON -DPHIGS_SANITIZE=ON >/dev/null
elif ! grep -q "^CMAKE_CXX_COMPILER:[A-Z]*=.*clang" "$build/CMakeCache.txt"; then
  echo "fuzz: $build is not a clang build; choose another FUZZ_BUILD" >&2
  exit 2
elif ! grep -q "^PHIGS_FUZZ:BOOL=ON" "$build/CMakeCache.txt"; then
  cmake -S . -B "$build" -DPHIGS_FUZZ=ON -DPHIGS_SANITIZE=ON >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target fuzz_archive_seeds "${targets[@]/#/fuzz_}" >"$build/fuzz-build.log" ||
  { tail -n 40 "$build/fuzz-build.log"; exit 2; }

# The seeds: the shipped and test files of each format, named after their paths, and
# tests/fuzz/corpus/TARGET (the session's seeds, and reproducers of fixed findings kept there).
shopt -s nullglob
seed() {
  local target=$1 dir=$work/seeds/$1 files=()
  rm -rf "$dir" && mkdir -p "$dir"
  case $target in
    crv) files=(apps/acsynt/data/*.crv tests/data/curvemap/*.crv tests/data/session/open.crv) ;;
    acm) files=(apps/acsynt/data/*.acm tests/data/session/bad_sections.acm tests/fuzz/data/*.acm) ;;
    archive) "$build/tests/fuzz/fuzz_archive_seeds" "$dir" ;;
    script) files=(apps/acsynt/data/demo.session tests/fuzz/corpus/session/*) ;;
    session) files=(apps/acsynt/data/demo.session) ;;
  esac
  files+=(tests/fuzz/corpus/"$target"/*)
  for file in "${files[@]}"; do cp "$file" "$dir/${file//\//_}"; done
}

# One target; leaves $work/TARGET.log and, on a finding, $work/TARGET.failed.
run() {
  local target=$1 seconds_override=FUZZ_SECONDS_$1 timeout_override=FUZZ_TIMEOUT_$1
  local time=${!seconds_override:-$seconds} timeout=${!timeout_override:-${FUZZ_TIMEOUT:-10}}
  shift
  rm -f "$work/$target.failed"
  # From the work directory: the session target looks names up in the working directory too.
  (cd "$work" && "$build/tests/fuzz/fuzz_$target" -max_total_time="$time" \
    -max_len="${FUZZ_MAX_LEN:-1048576}" -timeout="$timeout" -rss_limit_mb="${FUZZ_RSS_MB:-2048}" \
    -dict="$root/tests/fuzz/dict/$target.dict" -artifact_prefix="$work/findings/$target-" \
    -print_final_stats=1 "$@" "corpus/$target" "seeds/$target") >"$work/$target.log" 2>&1 ||
    touch "$work/$target.failed"
}

export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
mkdir -p "$work/findings"
for target in "${targets[@]}"; do
  seed "$target"
  mkdir -p "$work/corpus/$target"
done
for target in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= ${FUZZ_JOBS:-1})); do wait -n || true; done
  echo "fuzz: $target started (log $work/$target.log)"
  run "$target" "$@" &
done
wait
failed=()
for target in "${targets[@]}"; do
  if [ -f "$work/$target.failed" ]; then
    failed+=("$target")
    echo "fuzz: $target FOUND A PROBLEM; the end of its log:"
    tail -n 60 "$work/$target.log"
  else
    grep -E "^(#[0-9]+[[:space:]]+DONE|stat::peak_rss_mb|INFO: exiting)" "$work/$target.log" |
      sed "s/^/fuzz: $target: /" || true
  fi
done
if ((${#failed[@]})); then
  echo "fuzz: findings in ${failed[*]}: reproducers in $work/findings/ (run the target on the file)"
  exit 1
fi
