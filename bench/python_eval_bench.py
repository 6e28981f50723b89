"""The procex Python module against procex eval's in-process evaluation, in
one run (BENCHMARKS.md, "Python and Blender"): a recipe loaded (not timed),
evaluated once with an empty cache and its meshes handed back as NumPy arrays
(vertices, faces, tags touched), as `procex eval` loads and evaluates it once.
Medians of N of wall time and of process CPU time, rounds alternating with
the C++ reference (build/bench/procex_recipe_eval_bench), which of the two
goes first alternating too (the machine warms or cools between them), ratios
per round; the load average before and after.

    PYTHONPATH=build/python python3 bench/python_eval_bench.py [RECIPE] [ROUNDS] [PER_ROUND]

With --instructions instead, the instructions each side executes per
evaluation, counted by valgrind's callgrind, which the machine's load does not
change: the C++ reference's evaluate and gather_meshes alone; for Python, a
run loading and evaluating N times less one only loading N times, so its count
also holds the interpreter's loop, the wrapping, the arrays and tearing down
the last evaluation's cache (an upper bound of what it adds).

    PYTHONPATH=build/python python3 bench/python_eval_bench.py --instructions [RECIPE] [N]
"""
import os
import re
import statistics
import subprocess
import sys
import time

import procex

BENCH = os.environ.get("PROCEX_RECIPE_EVAL_BENCH", "build/bench/procex_recipe_eval_bench")
mode = sys.argv.pop(1) if len(sys.argv) > 1 and sys.argv[1].startswith("--") else "--time"
recipe = sys.argv[1] if len(sys.argv) > 1 else "samples/house.pxg"


def evaluate_and_touch(r):
    for p in r.evaluate():
        (p.vertices, p.face_offsets, p.face_indices, p.face_tags)


def python_medians(per_round):
    evaluate_and_touch(procex.Recipe.load(recipe))  # warm-up, as the reference does
    wall, cpu = [], []
    for _ in range(per_round):
        fresh = procex.Recipe.load(recipe)  # an empty cache, as procex eval has
        start, cpu_start = time.perf_counter(), time.process_time()
        evaluate_and_touch(fresh)
        cpu.append((time.process_time() - cpu_start) * 1000)
        wall.append((time.perf_counter() - start) * 1000)
    return statistics.median(wall), statistics.median(cpu)


def cpp_medians(per_round):
    out = subprocess.run([BENCH, recipe, str(per_round)], check=True, capture_output=True, text=True).stdout.split()
    return float(out[out.index("wall_ms") + 1]), float(out[out.index("cpu_ms") + 1])


def timed(rounds, per_round):
    print(f"load average {os.getloadavg()[0]:.1f}; {rounds} rounds of {per_round} evaluations")
    ratios = {"wall": [], "cpu": []}
    for i in range(rounds):
        if i % 2 == 0:
            (cw, cc), (pw, pc) = cpp_medians(per_round), python_medians(per_round)
        else:
            (pw, pc), (cw, cc) = python_medians(per_round), cpp_medians(per_round)
        ratios["wall"].append(pw / cw)
        ratios["cpu"].append(pc / cc)
        print(f"wall: procex eval in-process {cw:.3f} ms, Python {pw:.3f} ms, ratio {pw / cw:.2f}; "
              f"cpu: {cc:.3f} ms, {pc:.3f} ms, ratio {pc / cc:.2f}")
    print(f"load average {os.getloadavg()[0]:.1f}")
    for kind, r in ratios.items():
        print(f"{kind} time ratio Python / C++: median {statistics.median(r):.2f} (min {min(r):.2f}, max {max(r):.2f})")


def callgrind(*command):
    """Instructions callgrind collected running command."""
    err = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *command],
                         check=True, capture_output=True, text=True).stderr
    return int(re.search(r"Collected : (\d+)", err).group(1))


def loop(n, evaluate):
    """What --instructions counts on the Python side: n loads, each evaluated or not."""
    evaluate_and_touch(procex.Recipe.load(recipe))
    for _ in range(n):
        fresh = procex.Recipe.load(recipe)
        if evaluate:
            evaluate_and_touch(fresh)


def instructions(n):
    me = [sys.executable, os.path.abspath(__file__), "--loop", recipe, str(n)]
    python = (callgrind(*me, "evaluate") - callgrind(*me, "load")) / n
    cpp = callgrind("--collect-atstart=no", "--toggle-collect=procex::Evaluator::evaluate*",
                    "--toggle-collect=procex::gather_meshes*", BENCH, recipe, str(n)) / (n + 1)  # and its warm-up
    print(f"instructions per evaluation of {recipe}: procex eval in-process {cpp:,.0f}, Python {python:,.0f}, "
          f"ratio {python / cpp:.3f}")


if mode == "--time":
    timed(int(sys.argv[2]) if len(sys.argv) > 2 else 5, int(sys.argv[3]) if len(sys.argv) > 3 else 100)
elif mode == "--instructions":
    instructions(int(sys.argv[2]) if len(sys.argv) > 2 else 200)
elif mode == "--loop":
    loop(int(sys.argv[2]), sys.argv[3] == "evaluate")
else:
    sys.exit(f"unknown option {mode}")
