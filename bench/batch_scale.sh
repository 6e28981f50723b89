#!/bin/sh
# The "Batch at scale" benchmark of BENCHMARKS.md (issue 18): `procex batch
# samples/city.pxg` over N synthetic footprints (bench/batch_footprints.py),
# into one .glb and into a folder of per-building .ply files, for each given
# executable in turn (e.g. this build and a reference build of main), 2 jobs.
# One line per run: wall and CPU seconds, buildings per second (wall), peak
# RSS; then peak RSS's growth between sizes (MB per 10,000 buildings, and the
# log-log slope). Run from the checkout.
# Usage: bench/batch_scale.sh PROCEX [PROCEX ...]
#   SIZES="1000 10000 100000" and KINDS="glb folder" by default (a folder of a
#   million files takes hours: KINDS=glb SIZES="10000 100000 1000000" for the
#   million-building row).
set -eu
sizes=${SIZES:-"1000 10000 100000"}
kinds=${KINDS:-"glb folder"}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for n in $sizes; do python3 bench/batch_footprints.py "$n" "$out/f$n.geojson"; done
for exe in "$@"; do
  for kind in $kinds; do
    for n in $sizes; do
      if [ "$kind" = glb ]; then target="$out/city.glb"; else target="$out/city/"; fi
      rm -rf "$out/city.glb" "$out/city"
      # exit code 1: some footprints failed (reported)
      /usr/bin/time -f "%e %U %S %M" -o "$out/time" "$exe" batch samples/city.pxg --footprints "$out/f$n.geojson" \
        -o "$target" --format ply --report "$out/report.json" --jobs 2 --no-progress >/dev/null 2>"$out/err" ||
        [ $? -eq 1 ] || { cat "$out/err" >&2; exit 1; }
      set -- $(tail -n 1 "$out/time")
      echo "$exe $kind $n $1 $2 $3 $4 $(cut -d' ' -f1 /proc/loadavg)"
    done
  done
done | python3 -c '
import math, sys
rows = [l.split() for l in sys.stdin]
prev = {}
for exe, kind, n, wall, user, sys_s, rss, load in rows:
    n, wall, rss_mb = int(n), float(wall), int(rss) / 1024
    line = (f"{exe} {kind:6} n={n:>7} wall={wall:.2f}s cpu={float(user) + float(sys_s):.2f}s "
            f"buildings/s={n / wall:.0f} rss={rss_mb:.0f}MB load={load}")
    if (exe, kind) in prev:
        n0, r0 = prev[(exe, kind)]
        line += f"  growth: {(rss_mb - r0) / (n - n0) * 1e4:.1f} MB per 10k, slope {math.log(rss_mb / r0) / math.log(n / n0):.2f}"
    prev[(exe, kind)] = (n, rss_mb)
    print(line, flush=True)
'
