"""The procex Python module against procex eval's in-process evaluation, in
one run (BENCHMARKS.md, "Python and Blender"): a recipe evaluated with an
empty cache, its meshes handed back as NumPy arrays (vertices, faces, tags
touched), median of N in process CPU time (steadier than wall time on a
loaded machine), alternating with the C++ reference
(build/bench/procex_recipe_eval_bench).

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
per_round = 50


def python_median():
    r = procex.Recipe.load(recipe)
    r.evaluate()  # warm-up, as the reference does
    times = []
    for _ in range(per_round):
        fresh = procex.Recipe.load(recipe)  # an empty cache, as procex eval has
        start = time.process_time()
        parts = fresh.evaluate()
        for p in parts:
            (p.vertices, p.face_offsets, p.face_indices, p.face_tags)
        times.append((time.process_time() - start) * 1000)
    return statistics.median(times)


def cpp_median():
    out = subprocess.run([os.environ.get("PROCEX_RECIPE_EVAL_BENCH", "build/bench/procex_recipe_eval_bench"), recipe, str(per_round)], check=True,
                         capture_output=True, text=True).stdout.split()
    return float(out[1])


py, cpp = [], []
for _ in range(rounds):
    cpp.append(cpp_median())
    py.append(python_median())
for c, p in zip(cpp, py):
    print(f"procex eval in-process {c:.3f} ms, Python {p:.3f} ms, ratio {p / c:.2f}")
print(f"median: C++ {statistics.median(cpp):.3f} ms, Python {statistics.median(py):.3f} ms, "
      f"ratio {statistics.median(py) / statistics.median(cpp):.2f}")
