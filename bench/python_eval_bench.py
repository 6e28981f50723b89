"""The procex Python module against procex eval's in-process evaluation, in
one run (BENCHMARKS.md, "Python and Blender"): a recipe loaded (not timed),
evaluated once with an empty cache and its meshes handed back as NumPy arrays
(vertices, faces, tags touched), as `procex eval` loads and evaluates it once.
Medians of N of wall time and of process CPU time, rounds alternating with
the C++ reference (build/bench/procex_recipe_eval_bench), ratios per round.

    PYTHONPATH=build/python python3 bench/python_eval_bench.py [RECIPE] [ROUNDS]
"""
import os
import statistics
import subprocess
import sys
import time

import procex

recipe = sys.argv[1] if len(sys.argv) > 1 else "samples/house.pxg"
rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 5
per_round = 100


def python_medians():
    procex.Recipe.load(recipe).evaluate()  # warm-up, as the reference does
    wall, cpu = [], []
    for _ in range(per_round):
        fresh = procex.Recipe.load(recipe)  # an empty cache, as procex eval has
        start, cpu_start = time.perf_counter(), time.process_time()
        for p in fresh.evaluate():
            (p.vertices, p.face_offsets, p.face_indices, p.face_tags)
        cpu.append((time.process_time() - cpu_start) * 1000)
        wall.append((time.perf_counter() - start) * 1000)
    return statistics.median(wall), statistics.median(cpu)


def cpp_medians():
    bench = os.environ.get("PROCEX_RECIPE_EVAL_BENCH", "build/bench/procex_recipe_eval_bench")
    out = subprocess.run([bench, recipe, str(per_round)], check=True, capture_output=True, text=True).stdout.split()
    return float(out[out.index("wall_ms") + 1]), float(out[out.index("cpu_ms") + 1])


ratios = {"wall": [], "cpu": []}
for _ in range(rounds):
    (cw, cc), (pw, pc) = cpp_medians(), python_medians()
    ratios["wall"].append(pw / cw)
    ratios["cpu"].append(pc / cc)
    print(f"wall: procex eval in-process {cw:.3f} ms, Python {pw:.3f} ms, ratio {pw / cw:.2f}; "
          f"cpu: {cc:.3f} ms, {pc:.3f} ms, ratio {pc / cc:.2f}")
for kind, r in ratios.items():
    print(f"{kind} time ratio Python / C++: median {statistics.median(r):.2f} (min {min(r):.2f}, max {max(r):.2f})")
