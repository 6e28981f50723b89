#!/bin/sh
# The Batch benchmark of BENCHMARKS.md: `procex batch samples/city.pxg` over the
# whole OpenStreetMap corpus (data/footprints joined into one
# FeatureCollection), RUNS times each with 1 and 2 jobs, alternating; one line
# per run: wall and CPU seconds, peak RSS, the report's evaluate and write
# phases, footprints per second and the load average when it ended. Also
# checks that both job counts wrote the same bytes.
# Usage: bench/batch_city.sh [BUILD_DIR] [RUNS]   (from the checkout; default build, 3)
set -eu
build=${1:-build}
runs=${2:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 - data/footprints "$out/corpus.geojson" <<'PY'
import glob, json, sys
features = [f for p in sorted(glob.glob(sys.argv[1] + "/*.geojson")) for f in json.load(open(p))["features"]]
json.dump({"type": "FeatureCollection", "features": features}, open(sys.argv[2], "w"))
PY
n=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['features']))" "$out/corpus.geojson")
i=0
while [ "$i" -lt "$runs" ]; do
  for jobs in 1 2; do
    # exit code 1: some footprints failed (reported), which the corpus has
    /usr/bin/time -f "%e %U %S %M" -o "$out/time" "$build/app/cli/procex" batch samples/city.pxg \
      --footprints "$out/corpus.geojson" -o "$out/city_$jobs.glb" --report "$out/city_$jobs.json" \
      --jobs "$jobs" --no-progress >/dev/null 2>&1 || [ $? -eq 1 ]
    python3 - "$(tail -n 1 "$out/time")" "$out/city_$jobs.json" "$jobs" "$n" <<'PY'
import json, sys
wall, user, sys_s, rss = sys.argv[1].split()
s = json.load(open(sys.argv[2]))["summary"]
load = open("/proc/loadavg").read().split()[0]
print(f"jobs={sys.argv[3]} wall={wall}s cpu={float(user) + float(sys_s):.2f}s rss={int(rss) // 1024}MB "
      f"evaluate={s['evaluate_ms'] / 1000:.2f}s write={s['write_ms'] / 1000:.2f}s "
      f"footprints/s={int(sys.argv[4]) / float(wall):.0f} load={load}")
PY
  done
  cmp -s "$out/city_1.glb" "$out/city_2.glb" || { echo "1 and 2 jobs wrote different bytes" >&2; exit 1; }
  i=$((i + 1))
done
