#!/usr/bin/env python3
"""The scaling inputs of BENCHMARKS "Scale" (issue 18): five families of
polygons at n = 1k .. 1M vertices, written in the synthetic polyjson format
(core/io/polyjson.h) as <family>_<n>.json. Deterministic: the same arguments
give the same bytes.

  bench/scale_inputs.py OUT_DIR [--max-n N] [--sizes n,n,...] [--families a,b,...]

Families (n is the requested vertex count; the file holds about that many):
  regular   regular n-gon of circumradius 100 m
  star      alternating radii 100 and 90 m, jittered by up to 1 mm so that
            events do not all fall at one height (the symmetric star is a
            cluster case of issue 12, not a scaling one)
  comb      a bar 1 m deep with teeth 1 m wide and 4 m long, 1 m apart
  random    a random star-shaped polygon: sorted random angles, radii in
            [50, 100] m, so about half its corners are reflex
  holes     a square with k x k square holes, n = 4 + 4 k^2
"""
import argparse
import json
import math
import os
import random

SIZES = [1024, 4096, 16384, 65536, 262144, 1048576]


def regular(n):
    return [[[100.0 * math.cos(2 * math.pi * i / n), 100.0 * math.sin(2 * math.pi * i / n)] for i in range(n)]]


def star(n):
    rng = random.Random(n)
    n -= n % 2
    pts = []
    for i in range(n):
        r = (100.0 if i % 2 == 0 else 90.0) + rng.uniform(-1e-3, 1e-3)
        a = 2 * math.pi * i / n
        pts.append([r * math.cos(a), r * math.sin(a)])
    return [pts]


def comb(n):
    teeth = max(1, (n - 4) // 4)
    bottom = [[0.0, 0.0], [2.0 * teeth + 1.0, 0.0]]
    top = []
    for t in reversed(range(teeth)):  # right to left along the top of the bar
        x0 = 2.0 * t + 1.0
        top += [[x0 + 1.0, 1.0], [x0 + 1.0, 5.0], [x0, 5.0], [x0, 1.0]]
    return [bottom + [[2.0 * teeth + 1.0, 1.0]] + top + [[0.0, 1.0]]]


def random_star_shaped(n):
    rng = random.Random(n)
    angles = sorted(rng.uniform(0.0, 2 * math.pi) for _ in range(n))
    return [[[r * math.cos(a), r * math.sin(a)] for a, r in ((a, rng.uniform(50.0, 100.0)) for a in angles)]]


def holes(n):
    k = max(1, round(math.sqrt(max(n - 4, 4) / 4)))
    pitch = 3.0
    side = pitch * k + 1.0
    loops = [[[0.0, 0.0], [side, 0.0], [side, side], [0.0, side]]]
    for i in range(k):
        for j in range(k):
            x, y = 1.0 + pitch * i, 1.0 + pitch * j
            loops.append([[x, y], [x, y + 2.0], [x + 2.0, y + 2.0], [x + 2.0, y]])  # clockwise: a hole
    return loops


FAMILIES = {"regular": regular, "star": star, "comb": comb, "random": random_star_shaped, "holes": holes}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out_dir")
    parser.add_argument("--max-n", type=int, default=SIZES[-1])
    parser.add_argument("--sizes", default=",".join(map(str, SIZES)), help="the n to write (default: the scale run's)")
    parser.add_argument("--families", default=",".join(FAMILIES))
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    for family in args.families.split(","):
        if family not in FAMILIES:
            parser.error(f"unknown family {family!r}; known: {', '.join(FAMILIES)}")
        for n in (s for s in map(int, args.sizes.split(",")) if s <= args.max_n):
            path = os.path.join(args.out_dir, f"{family}_{n}.json")
            with open(path + ".tmp", "w") as f:
                json.dump({"loops": FAMILIES[family](n)}, f, separators=(",", ":"))
            os.replace(path + ".tmp", path)
            print(path)


if __name__ == "__main__":
    main()
