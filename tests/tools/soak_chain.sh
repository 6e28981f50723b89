#!/bin/bash
# soak_chain.sh BINARY SUITE FIRST LAST DIR: runs a generated class's soak
# budget (PROCEX_SOAK=1) over seeds FIRST..LAST one seed at a time, so that a
# soak of hours can be paused, stopped and resumed, and shares the machine
# with other work:
#   BINARY  the test program holding the class (build/tests/procex_large_tests)
#   SUITE   the class's suite (GeneratedLargeStars: run_generated.h)
#   DIR     where it keeps DIR/chain.log (a line a seed: its time, exit status
#           and the class's own line of cases, failures and retries), the
#           output of a seed that failed (DIR/seed_N.out) and the fixtures of
#           failures (DIR/findings, PROCEX_FINDINGS_DIR)
# A seed the log already shows passed is not run again. Before each seed it
# waits while DIR/PAUSE exists and ends if DIR/STOP does. At the end, and
# with `soak_chain.sh --summary DIR`, it prints the log's totals as TESTING.md
# records them: seeds passed, seeds that failed (at any run), sweeps retried.
set -uo pipefail

summary() {
  awk '$2 == "seed" && $4 ~ /^rc=/ {
         seed = $3 + 0
         if ($4 == "rc=0") passed[seed] = 1; else failed[seed] = 1
         for (i = 2; i <= NF; ++i) if ($i == "sweeps") retried[seed] = $(i - 1)
       }
       END {
         for (s in passed) {
           ++p; r += retried[s]
           if (p == 1 || s + 0 < lo) lo = s + 0
           if (p == 1 || s + 0 > hi) hi = s + 0
         }
         for (s in failed) ++f
         if (p == 0) printf "no seed passed, %d failed\n", f
         else printf "%d seeds passed (from %d to %d), %d failed, %d sweeps retried\n", p, lo, hi, f, r
       }' "$1/chain.log"
}

if [ "${1:-}" = "--summary" ]; then
  [ $# -eq 2 ] && [ -f "$2/chain.log" ] || { echo "usage: soak_chain.sh --summary DIR (a DIR with chain.log)" >&2; exit 2; }
  summary "$2"
  exit 0
fi
[ $# -eq 5 ] || { echo "usage: soak_chain.sh BINARY SUITE FIRST LAST DIR | --summary DIR" >&2; exit 2; }
binary=$1 suite=$2 first=$3 last=$4 dir=$5
[[ "$first" =~ ^[0-9]+$ && "$last" =~ ^[0-9]+$ ]] || { echo "soak_chain.sh: FIRST and LAST are seeds" >&2; exit 2; }
[ -x "$binary" ] || { echo "soak_chain.sh: $binary is not a program" >&2; exit 2; }
"$binary" --gtest_list_tests --gtest_filter="Parts/$suite.*/0" | grep -q EveryCasePassesEveryProperty ||
  { echo "soak_chain.sh: $binary has no generated class $suite (run_generated.h)" >&2; exit 2; }
mkdir -p "$dir/findings"
log=$dir/chain.log
touch "$log"
for ((seed = first; seed <= last; ++seed)); do
  grep -q " seed $seed rc=0 " "$log" && continue
  while [ -e "$dir/PAUSE" ] && [ ! -e "$dir/STOP" ]; do sleep 10; done
  if [ -e "$dir/STOP" ]; then echo "$(date -u +%FT%TZ) stopped before seed $seed" >> "$log"; exit 0; fi
  start=$(date +%s)
  out=$(PROCEX_SOAK=1 PROCEX_SEEDS=$seed PROCEX_FINDINGS_DIR=$dir/findings "$binary" --gtest_filter="Parts/$suite.*/0" 2>&1)
  rc=$?
  line=$(grep '^class ' <<< "$out")
  if [ -z "$line" ] && [ "$rc" -eq 0 ]; then rc=1; fi  # ended without its class's line
  echo "$(date -u +%FT%TZ) seed $seed rc=$rc $(($(date +%s) - start)) s: $line" >> "$log"
  [ "$rc" -eq 0 ] || printf '%s\n' "$out" > "$dir/seed_$seed.out"
done
summary "$dir"
