"""procex.batch_iter against procex.batch and `procex batch` at N generated
footprints (BENCHMARKS.md, "procex.batch_iter ..."; issue 18): each run a
process of its own, rounds interleaving the kinds (the machine's load moves
between them); one line a run with wall and CPU seconds, cores busy (CPU /
wall) and peak RSS, then per kind the median wall time and its ratio to
procex.batch's. The iterator's caller keeps nothing (it counts the buildings
that are ok and have meshes), as a city's caller that writes them out would.

    python3 bench/batch_iter_bench.py [--slow-every K] N ROUNDS JOBS PROCEX_CLI [LABEL=MODULE_DIR ...]

--slow-every K: every K-th footprint (from the 6th) a 1024-vertex star, about
150 times a generated footprint's time with this recipe, as a city has a few
large, intricate buildings among its houses: what a batch does while it
waits for one of them.

Each LABEL=MODULE_DIR is a folder holding a procex module (e.g. build/python,
or a copy of another commit's) whose batch_iter runs as "iter LABEL"; the
first one's procex.batch runs as "batch", and PROCEX_CLI as "cli" (writing
one .glb into a temporary folder, with --report: its evaluate_ms too; "-":
none).
"""
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

RUN = """
import resource, sys, time
import procex
recipe = procex.Recipe.load(sys.argv[1])
start, cpu = time.perf_counter(), time.process_time()
n = 0
if sys.argv[3] == "iter":
    for b in procex.batch_iter(recipe, sys.argv[2], jobs=int(sys.argv[4])):
        n += b.status == "ok" and len(b.meshes) > 0
else:
    n = sum(b.status == "ok" and len(b.meshes) > 0 for b in procex.batch(recipe, sys.argv[2], jobs=int(sys.argv[4])))
print(n, time.perf_counter() - start, time.process_time() - cpu, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def run_python(module_dir, kind, footprints, jobs):
    env = dict(os.environ, PYTHONPATH=module_dir)
    r = subprocess.run([sys.executable, "-c", RUN, os.path.join(ROOT, "samples", "city.pxg"), footprints, kind,
                        str(jobs)], capture_output=True, text=True, env=env, check=True)
    n, wall, cpu, rss = r.stdout.split()
    return int(n), float(wall), float(cpu), int(rss), None


def run_cli(cli, footprints, jobs, folder):
    report = os.path.join(folder, "report.json")
    start = time.perf_counter()
    child = subprocess.Popen([cli, "batch", os.path.join(ROOT, "samples", "city.pxg"), "--footprints", footprints,
                              "-o", os.path.join(folder, "city.glb"), "--report", report, "--jobs", str(jobs),
                              "--no-progress"], stdout=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    assert child.returncode == 0, child.returncode
    summary = json.load(open(report))["summary"]
    return summary["ok"], wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss, summary["evaluate_ms"] / 1000


def add_slow(footprints, every):
    collection = json.load(open(footprints))
    n = 1024
    for i in range(5, len(collection["features"]), every):
        cx, cy = collection["features"][i]["geometry"]["coordinates"][0][0]
        ring = [[round(cx + 15 * (1 if k % 2 else 0.6) * math.cos(2 * math.pi * k / n), 3),
                 round(cy + 15 * (1 if k % 2 else 0.6) * math.sin(2 * math.pi * k / n), 3)] for k in range(n)]
        collection["features"][i]["geometry"] = {"type": "Polygon", "coordinates": [ring + [ring[0]]]}
    json.dump(collection, open(footprints, "w"))


def main():
    args = sys.argv[1:]
    slow_every = 0
    if args[0] == "--slow-every":
        slow_every, args = int(args[1]), args[2:]
    n, rounds, jobs, cli = int(args[0]), int(args[1]), int(args[2]), args[3]
    modules = [a.split("=", 1) for a in args[4:]] or [["build", os.path.join(ROOT, "build", "python")]]
    with tempfile.TemporaryDirectory() as folder:
        footprints = os.path.join(folder, f"{n}.geojson")
        subprocess.run([sys.executable, os.path.join(ROOT, "bench", "batch_footprints.py"), str(n), footprints],
                       check=True)
        if slow_every:
            add_slow(footprints, slow_every)
        kinds = [("iter " + label, lambda d=d: run_python(d, "iter", footprints, jobs)) for label, d in modules]
        kinds.append(("batch", lambda: run_python(modules[0][1], "batch", footprints, jobs)))
        if cli != "-":
            kinds.append(("cli", lambda: run_cli(cli, footprints, jobs, folder)))
        walls = {name: [] for name, _ in kinds}
        slow = f", every {slow_every}th a 1024-vertex star" if slow_every else ""
        print(f"{n} footprints{slow}, jobs={jobs}, {rounds} rounds; load before {os.getloadavg()[0]:.1f}")
        for r in range(rounds):
            order = kinds if r % 2 == 0 else kinds[::-1]
            for name, run in order:
                ok, wall, cpu, rss, evaluate = run()
                walls[name].append(wall)
                extra = f", evaluate {evaluate:.1f} s" if evaluate is not None else ""
                print(f"round {r} {name:12} {ok} ok  wall {wall:6.1f} s  cpu {cpu:6.1f} s  busy {cpu / wall:.2f}  "
                      f"peak {rss / 1024:.0f} MB{extra}  load {os.getloadavg()[0]:.1f}", flush=True)
        base = statistics.median(walls["batch"])
        for name, w in walls.items():
            print(f"{name:12} median wall {statistics.median(w):6.1f} s  ({statistics.median(w) / base:.2f}x batch)")


if __name__ == "__main__":
    main()
