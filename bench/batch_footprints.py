#!/usr/bin/env python3
"""Synthetic footprints for the batch scaling benchmark (BENCHMARKS "Batch at
scale", issue 18): N buildings as one GeoJSON FeatureCollection in metres
(no CRS), rectangles and L plans of 8-24 m, slightly turned, one per 40 m
cell of a square grid. Deterministic: the same arguments give the same bytes.

  bench/batch_footprints.py N OUT.geojson
"""
import json
import math
import random
import sys


def footprint(rng, cx, cy):
    w, d = rng.uniform(8, 24), rng.uniform(8, 24)
    if rng.random() < 0.3:  # an L: a corner cut out
        cw, cd = w * rng.uniform(0.3, 0.6), d * rng.uniform(0.3, 0.6)
        pts = [(0, 0), (w, 0), (w, d - cd), (w - cw, d - cd), (w - cw, d), (0, d)]
    else:
        pts = [(0, 0), (w, 0), (w, d), (0, d)]
    a = rng.uniform(-0.3, 0.3)
    c, s = math.cos(a), math.sin(a)
    ring = [[round(cx + (x - w / 2) * c - (y - d / 2) * s, 3), round(cy + (x - w / 2) * s + (y - d / 2) * c, 3)]
            for x, y in pts]
    return ring + [ring[0]]


def main():
    n, out = int(sys.argv[1]), sys.argv[2]
    rng = random.Random(18)
    side = math.ceil(math.sqrt(n))
    with open(out, "w") as f:  # written feature by feature: a million fit in little memory
        f.write('{"type": "FeatureCollection", "features": [\n')
        for i in range(n):
            ring = footprint(rng, 40.0 * (i % side), 40.0 * (i // side))
            feature = {"type": "Feature", "id": "b%d" % i, "properties": {},
                       "geometry": {"type": "Polygon", "coordinates": [ring]}}
            f.write(("," if i else "") + json.dumps(feature, separators=(",", ":")) + "\n")
        f.write("]}\n")


if __name__ == "__main__":
    main()
