#!/bin/sh
# The Batch benchmark of BENCHMARKS.md: `procex batch samples/city.pxg` over the
# whole OpenStreetMap corpus (data/footprints joined into one
# FeatureCollection), RUNS times each with 1 and 2 jobs, alternating; one line
# per run: wall and CPU seconds, peak RSS, the report's evaluate and write
# phases, footprints per second and the load average when it ended. Also
# checks that both job counts wrote the same bytes.
#
# In the same runs, with 2 jobs (issue 14's "at most 1.25x" is measured
# against runs beside it, not against numbers from another day):
# - "materials": the same recipe with Material nodes (brick walls and gables,
#   tiled roofs, both textured, samples/textures), so every .glb primitive
#   carries a PBR material and the two images are embedded;
# - "reference" and "reference_materials": REFERENCE, another procex
#   executable (e.g. main's, or this commit built without the _TAG attribute,
#   see BENCHMARKS.md), on the plain recipe and on the one with materials.
# Then per kind the mean CPU seconds and the highest peak RSS, and their
# ratios: materials to plain for each executable, this one's to the
# reference's for each recipe.
# Usage: bench/batch_city.sh [BUILD_DIR] [RUNS] [REFERENCE]   (from the checkout; default build, 3)
set -eu
build=${1:-build}
runs=${2:-3}
reference=${3:-}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 - data/footprints "$out/corpus.geojson" <<'PY'
import glob, json, sys
features = [f for p in sorted(glob.glob(sys.argv[1] + "/*.geojson")) for f in json.load(open(p))["features"]]
json.dump({"type": "FeatureCollection", "features": features}, open(sys.argv[2], "w"))
PY
# samples/city.pxg with a Material node per tag after its output, its textures and
# the meshes it places (windows, doors) beside it, as the recipe's folder has them.
cp -r samples/textures "$out/textures"
cp -r samples/meshes "$out/meshes"
python3 - samples/city.pxg "$out/materials.pxg" <<'PY'
import json, sys
recipe = json.load(open(sys.argv[1]))
looks = [("wall", "textures/brick.png", 0.8, 0.85), ("gable", "textures/brick.png", 0.8, 0.85),
         ("roof", "textures/roof_tiles.png", 1.2, 0.6), ("party", "", 1.0, 0.9)]
last = max(n["id"] for n in recipe["nodes"])
into = next(l for l in recipe["links"] if l["to"] == "@mesh")
for k, (tag, texture, tile, roughness) in enumerate(looks):
    node = last + 1 + k
    recipe["nodes"].append({"id": node, "type": "Material", "version": 1, "params": {
        "tag": tag, "colour": [1.0, 1.0, 1.0] if texture else [0.7, 0.68, 0.65], "roughness": roughness,
        "metallic": 0.0, "texture": texture, "tile_size": tile}})
    into["to"] = f"{node}.mesh"
    into = {"from": f"{node}.mesh", "to": "@mesh"}
    recipe["links"].append(into)
json.dump(recipe, open(sys.argv[2], "w"))
PY
n=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['features']))" "$out/corpus.geojson")
# One run: KIND PROCEX RECIPE JOBS; prints its line.
run() {
  # exit code 1: some footprints failed (reported), which the corpus has
  /usr/bin/time -f "%e %U %S %M" -o "$out/time" "$2" batch "$3" \
    --footprints "$out/corpus.geojson" -o "$out/$1_$4.glb" --report "$out/$1_$4.json" \
    --jobs "$4" --no-progress >/dev/null 2>&1 || [ $? -eq 1 ]
  python3 - "$(tail -n 1 "$out/time")" "$out/$1_$4.json" "$4" "$n" "$1" "$out/lines" <<'PY'
import json, sys
wall, user, sys_s, rss = sys.argv[1].split()
s = json.load(open(sys.argv[2]))["summary"]
# A run whose buildings all failed (a file the recipe names missing) measures nothing.
if not s.get("ok"):
    sys.exit(f"{sys.argv[5]}: no building was made: {s}")
load = open("/proc/loadavg").read().split()[0]
line = (f"{sys.argv[5]} jobs={sys.argv[3]} wall={wall}s cpu={float(user) + float(sys_s):.2f}s rss={int(rss) // 1024}MB "
        f"evaluate={s['evaluate_ms'] / 1000:.2f}s write={s['write_ms'] / 1000:.2f}s "
        f"footprints/s={int(sys.argv[4]) / float(wall):.0f} load={load}")
print(line, flush=True)
open(sys.argv[6], "a").write(line + "\n")
PY
}
i=0
while [ "$i" -lt "$runs" ]; do
  for jobs in 1 2; do run plain "$build/app/cli/procex" samples/city.pxg "$jobs"; done
  cmp -s "$out/plain_1.glb" "$out/plain_2.glb" || { echo "1 and 2 jobs wrote different bytes" >&2; exit 1; }
  run materials "$build/app/cli/procex" "$out/materials.pxg" 2
  if [ -n "$reference" ]; then
    run reference "$reference" samples/city.pxg 2
    run reference_materials "$reference" "$out/materials.pxg" 2
  fi
  i=$((i + 1))
done
python3 - "$out/lines" <<'PY'
import re, sys
cpu, rss = {}, {}
for line in open(sys.argv[1]):
    kind, jobs = line.split()[0], line.split()[1]
    if jobs != "jobs=2":
        continue
    cpu.setdefault(kind, []).append(float(re.search(r"cpu=([\d.]+)s", line).group(1)))
    rss[kind] = max(rss.get(kind, 0), int(re.search(r"rss=(\d+)MB", line).group(1)))
mean = {k: sum(v) / len(v) for k, v in cpu.items()}
for kind in mean:
    print(f"{kind} (2 jobs): mean cpu={mean[kind]:.2f}s peak rss={rss[kind]}MB")
for kind, base in (("materials", "plain"), ("reference_materials", "reference"), ("plain", "reference"),
                   ("materials", "reference_materials")):
    if kind in mean and base in mean:
        print(f"{kind} / {base}: cpu {mean[kind] / mean[base]:.2f}x, peak rss {rss[kind] / rss[base]:.2f}x")
PY
