#!/bin/sh
# Soak (label soak: run by hand, `ctest -L soak`, never in CI): procex batch
# over N generated footprints (bench/batch_footprints.py; 100,000 by default)
# into one streamed .glb, and the same in 4 shards joined by procex merge: the
# merged file has the one run's bytes and every building in its report; the
# Khronos validator finds no error or warning in it. Prints each step's peak
# RSS (recorded in TESTING.md, not asserted: it depends on the machine).
# Usage: batch_scale_soak.sh PROCEX SOURCE_DIR [N]
set -eu
exe=$1
src=$2
n=${3:-100000}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
/usr/bin/python3 "$src/bench/batch_footprints.py" "$n" "$out/footprints.geojson"
step() {
  name=$1
  shift
  /usr/bin/time -f "%M" -o "$out/rss" "$@" >/dev/null 2>"$out/err" || { cat "$out/err" >&2; echo "$name failed" >&2; exit 1; }
  echo "$name: peak RSS $(($(tail -n 1 "$out/rss") / 1024)) MB"
}
batch() {
  name=$1
  shift
  step "$name" "$exe" batch "$src/samples/city.pxg" --footprints "$out/footprints.geojson" --no-progress "$@"
}
batch "batch of $n" -o "$out/all.glb" --report "$out/all.json"
parts=""
for i in 0 1 2 3; do
  batch "shard $i/4" --shard "$i/4" -o "$out/part$i.glb" --report "$out/part$i.json"
  parts="$parts $out/part$i.json $out/part$i.glb"
done
# shellcheck disable=SC2086
step "merge of 4" "$exe" merge $parts -o "$out/merged.glb" --report "$out/merged.json"
cmp "$out/all.glb" "$out/merged.glb"
node "$src/tools/validate_gltf.mjs" "$out/all.glb" >"$out/validator.json" || [ $? -eq 1 ]
/usr/bin/python3 - "$out" "$n" <<'PY'
import json, sys
out, n = sys.argv[1], int(sys.argv[2])
one, merged = (json.load(open(f"{out}/{name}.json")) for name in ("all", "merged"))
ids = lambda r: [(b["index"], b["id"], b["status"]) for b in r["buildings"]]
assert len(one["buildings"]) == n and ids(one) == ids(merged), "the merged report's buildings are not the one run's"
assert one["summary"]["ok"] == n, one["summary"]
issues = json.load(open(f"{out}/validator.json"))["issues"]
assert issues["numErrors"] == 0 and issues["numWarnings"] == 0, issues["messages"][:5]
print(f"{n} buildings: merged bytes and report equal the one run's; validator: 0 errors, 0 warnings, {issues['numInfos']} infos")
PY
