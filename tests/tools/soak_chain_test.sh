#!/bin/bash
# soak_chain_test.sh TESTS: soak_chain.sh over three seeds of the grid class in
# TESTS (procex_core_tests) logs a line a seed, runs none again that passed,
# stops at STOP, refuses a suite the program lacks, and sums a log.
set -euo pipefail
tests=$1
chain=$(dirname "$0")/soak_chain.sh
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "$1"; cat "$dir/chain.log" 2>/dev/null; exit 1; }
"$chain" "$tests" GeneratedGrid 0 2 "$dir" > "$dir/out"
[ "$(grep -c ' seed [0-2] rc=0 .*class grid seeds [0-2]\.\.[0-2]: 1 cases, 0 failed' "$dir/chain.log")" -eq 3 ] ||
  fail "expected three passing seeds"
grep -qx '3 seeds passed (from 0 to 2), 0 failed, 0 sweeps retried' "$dir/out" || fail "summary: $(cat "$dir/out")"
"$chain" "$tests" GeneratedGrid 0 3 "$dir" > /dev/null
[ "$(grep -c ' seed ' "$dir/chain.log")" -eq 4 ] || fail "passed seeds were run again"
touch "$dir/STOP"
"$chain" "$tests" GeneratedGrid 4 9 "$dir" > /dev/null
grep -q 'stopped before seed 4' "$dir/chain.log" || fail "STOP did not stop it"
rm "$dir/STOP"
if "$chain" "$tests" GeneratedNoSuchClass 0 0 "$dir" 2> "$dir/err"; then fail "a suite the program lacks was taken"; fi
grep -q 'has no generated class GeneratedNoSuchClass' "$dir/err" || fail "unexpected message: $(cat "$dir/err")"
echo "2026-12-07T00:00:00Z seed 7 rc=1 5 s: class grid seeds 7..7: 1 cases, 1 failed, 2 sweeps closed after a retry" >> "$dir/chain.log"
[ "$("$chain" --summary "$dir")" = "4 seeds passed (from 0 to 3), 1 failed, 0 sweeps retried" ] ||
  fail "summary with a failure: $("$chain" --summary "$dir")"
echo ok
