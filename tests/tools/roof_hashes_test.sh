#!/bin/bash
# roof_hashes_test.sh HASHES FIXTURE: procex_roof_hashes over generated cases of
# three classes and a fixture prints a line a sweep (the case's own, its
# transforms', CGAL's plan's), each with a 16-digit hash, the same lines twice,
# and refuses a class without seeds.
set -euo pipefail
hashes=$1 fixture=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$hashes" grid 0-3 angles 7-8 random_polygons 1 "$fixture" > "$tmp/a"
"$hashes" grid 0-3 angles 7-8 random_polygons 1 "$fixture" > "$tmp/b"
cmp "$tmp/a" "$tmp/b" || { echo "two runs differ"; diff "$tmp/a" "$tmp/b"; exit 1; }
# Each grid case is swept with its three transforms and CGAL's plan: 5 lines.
[ "$(grep -c '^grid [0-3][ ,]' "$tmp/a")" -eq 20 ] || { echo "expected 20 grid lines:"; cat "$tmp/a"; exit 1; }
grep -q "^random_polygons 1, CGAL's plan [0-9a-f]\{16\} [0-9]* vertices" "$tmp/a" || { echo "no random polygon line:"; cat "$tmp/a"; exit 1; }
grep -q "^$fixture " "$tmp/a" || { echo "no fixture line:"; cat "$tmp/a"; exit 1; }
if bad=$(grep -v ' [0-9a-f]\{16\} ' "$tmp/a"); then echo "lines without a hash: $bad"; exit 1; fi
if "$hashes" grid 2> "$tmp/err"; then echo "a class without seeds was taken"; exit 1; fi
grep -q "give its seeds" "$tmp/err" || { echo "unexpected message:"; cat "$tmp/err"; exit 1; }
echo "ok: $(wc -l < "$tmp/a") sweeps"
