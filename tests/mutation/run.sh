#!/usr/bin/env bash
# The mutation check of the engine's tests (TESTING.md, "Mutation check"):
# applies each fault of tests/mutation/mutants.txt in turn to a copy of the
# tree, builds the core tests in their own build folder (Release, no studio,
# no benchmarks) and runs them but the corpus-wide suites; a fault no test
# catches "survives". Prints one line per mutant and a score.
#   tests/mutation/run.sh [ID...]     (default: every mutant; from the checkout)
# Environment: PROCEX_MUTATION_DIR (default /tmp/procex-mutation), PROCEX_JOBS (2),
# PROCEX_MUTATION_TIMEOUT (seconds per test run, default 900; a timeout counts as caught).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
work=${PROCEX_MUTATION_DIR:-/tmp/procex-mutation}
jobs=${PROCEX_JOBS:-2}
limit=${PROCEX_MUTATION_TIMEOUT:-900}
# The corpus-wide suites take minutes each; the engine's hand-made tests are the ones judged here.
filter='-Osm/*:Synthetic/*'

mkdir -p "$work"
# Contents compared, times not kept: a file that changed gets a new time, so the build sees it
# (kept times can be older than the objects of an earlier run, which ninja then takes as current).
rsync -rlpc --delete --exclude '/build*' --exclude '/.git' --exclude '/out' "$root/" "$work/src/"
export CCACHE_BASEDIR="$work/src"
cmake -S "$work/src" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPROCEX_STUDIO=OFF -DPROCEX_BENCH=OFF >/dev/null
tests="$work/build/tests/procex_core_tests"
build() { cmake --build "$work/build" --target procex_core_tests -j "$jobs" >"$work/build.log" 2>&1; }
# A mutant is caught by its first failing test: the rest need not run (the unmutated run goes whole).
run_tests() { timeout "$limit" "$tests" --gtest_filter="$filter" --gtest_brief=1 "$@" >"$work/test.log" 2>&1; }

build || { echo "the unmutated tree does not build (see $work/build.log)"; exit 2; }
run_tests || { echo "the unmutated tests fail (see $work/test.log)"; exit 2; }

# id @@ file @@ from @@ to @@ what
mapfile -t lines < <(grep -v '^\s*#' tests/mutation/mutants.txt | grep -v '^\s*$')
caught=0 survived=0 stale=0
for line in "${lines[@]}"; do
  IFS=$'\x1f' read -r id file from to what <<<"${line// @@ /$'\x1f'}"
  if [ $# -gt 0 ] && ! printf '%s\n' "$@" | grep -qx "$id"; then continue; fi
  if ! python3 - "$work/src/$file" "$from" "$to" <<'PY'
import sys
path, old, new = sys.argv[1:4]
text = open(path).read()
if text.count(old) != 1:
    sys.exit(1)
open(path, "w").write(text.replace(old, new))
PY
  then
    echo "STALE     $id: the text is not in $file once (update mutants.txt)"
    stale=$((stale + 1))
    continue
  fi
  if ! build; then
    result="CAUGHT    $id (does not compile)"
    caught=$((caught + 1))
  elif run_tests --gtest_fail_fast; then
    result="SURVIVED  $id: $what"
    survived=$((survived + 1))
  else
    result="CAUGHT    $id: $(grep -m1 -E '^\[  FAILED  \]' "$work/test.log" | sed 's/\[  FAILED  \] //' || echo timeout)"
    caught=$((caught + 1))
  fi
  echo "$result"
  cp "$root/$file" "$work/src/$file"
done
build >/dev/null || true
total=$((caught + survived))
echo "score: $caught of $total mutants caught ($survived survived, $stale stale)"
[ "$survived" -eq 0 ] && [ "$stale" -eq 0 ]
