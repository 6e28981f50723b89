"""procex.batch_iter: batch()'s buildings handed over one at a time, in the
same order and with the same meshes and features; a bad footprint reported
in its item while the rest go on; dropped early, no worker thread and no
temporary file left; its peak memory not growing with the footprints, and a few
dozen bytes kept a footprint."""
import gc
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import procex
from conftest import ROOT, SAMPLES
from worker_threads import workers, workers_once_joined

BLOCK = SAMPLES / "footprints" / "sample_block.geojson"


def city():
    return procex.Recipe.load(SAMPLES / "city.pxg")


def assert_same_buildings(want, got):
    assert [(b.index, b.id, b.status) for b in got] == [(b.index, b.id, b.status) for b in want]
    for a, b in zip(want, got):
        assert a.reason == b.reason and a.warnings == b.warnings and a.feature == b.feature, a.id
        assert len(a.meshes) == len(b.meshes), a.id
        for m, n in zip(a.meshes, b.meshes):
            assert (m.building, m.tags) == (n.building, n.tags)
            for name in ("vertices", "face_offsets", "face_indices", "face_tags", "source_edges"):
                np.testing.assert_array_equal(getattr(m, name), getattr(n, name), err_msg=f"{a.id} {name}")
            assert [(p.mesh.name, p.matrix.tolist()) for p in m.placed] == \
                [(p.mesh.name, p.matrix.tolist()) for p in n.placed]


def open_files():
    return sorted(os.readlink(f"/proc/self/fd/{fd}") for fd in os.listdir("/proc/self/fd")
                  if os.path.exists(f"/proc/self/fd/{fd}"))


def test_dropped_early_leaves_no_thread_or_temporary_file():
    # First in the file, with jobs=1: a later test's TBB workers may carry the name on (workers()).
    gc.collect()
    workers_before, files_before = workers(), open_files()
    it = procex.batch_iter(city(), BLOCK, jobs=1)
    # The footprints' spool is an unnamed temporary file open while the iterator lives.
    assert any("(deleted)" in f or "#" in f for f in set(open_files()) - set(files_before))
    assert workers() == workers_before + 1  # its worker
    got = [next(it) for _ in range(3)]
    assert [b.index for b in got] == [0, 1, 2]
    del it
    gc.collect()
    assert workers_once_joined(workers_before) <= workers_before
    assert open_files() == files_before
    # close() and a with block do the same, and an iterator closed yields nothing more.
    with procex.batch_iter(city(), BLOCK, jobs=1) as it:
        next(it)
    assert workers_once_joined(workers_before) <= workers_before and open_files() == files_before
    with pytest.raises(StopIteration):
        next(it)


@pytest.mark.parametrize("jobs", [1, 2])
def test_yields_what_batch_returns_in_order(jobs):
    want = procex.batch(city(), BLOCK, jobs=jobs)
    it = procex.batch_iter(city(), BLOCK, jobs=jobs)
    assert len(it) == 18 and iter(it) is it
    assert_same_buildings(want, list(it))
    with pytest.raises(StopIteration):
        next(it)


def star(n, radius):
    """A star of n vertices, alternately at radius and 0.6 radius: with the
    city recipe about 150 times a generated footprint's time at n = 1024."""
    ring = [[radius * (1 if k % 2 else 0.6) * math.cos(2 * math.pi * k / n),
             radius * (1 if k % 2 else 0.6) * math.sin(2 * math.pi * k / n)] for k in range(n)]
    return {"type": "Polygon", "coordinates": [ring + [ring[0]]]}


def test_a_slow_building_among_many_keeps_the_order(tmp_path):
    """More buildings than the iterator holds (64 a job ahead, 64 a job
    ready: 256 at jobs=2), a slow one early and one further on: the others
    are evaluated past it while the caller waits for it
    (tests/app/ordered_pipeline_test.cc shows that without timing), and still
    come out in footprint order with batch()'s results."""
    path = tmp_path / "many.geojson"
    subprocess.run([sys.executable, ROOT / "bench" / "batch_footprints.py", "600", path], check=True)
    collection = json.loads(path.read_text())
    for i in (5, 400):
        collection["features"][i]["geometry"] = star(1024, 15)
    want = procex.batch(city(), collection, jobs=2)
    got = list(procex.batch_iter(city(), collection, jobs=2))
    assert [b.index for b in got] == list(range(600))
    assert [b.status for b in got].count("ok") == 600
    assert len(got[5].meshes[0].face_offsets) > 1024  # the star, evaluated
    assert_same_buildings(want, got)


def test_a_bad_footprint_is_reported_and_the_rest_go_on(tmp_path):
    collection = json.loads(BLOCK.read_text())
    collection["features"][3]["geometry"]["coordinates"] = "not coordinates"
    collection["features"][7]["geometry"]["coordinates"] = [[[0, 0], [10, 10], [10, 0], [0, 10], [0, 0]]]
    path = tmp_path / "bad.geojson"
    path.write_text(json.dumps(collection))
    for footprints in (path, collection):  # a file read into the spool, and a dict
        got = list(procex.batch_iter(city(), footprints, jobs=2))
        assert [b.status for b in got].count("ok") == 16
        assert got[3].status == "refused" and "coordinates" in got[3].reason and got[3].meshes == []
        assert got[3].feature is None
        assert got[7].status == "refused" and "intersects itself" in got[7].reason
        assert_same_buildings(procex.batch(city(), footprints, jobs=2), got)


PEAK = """
import resource, sys
import procex
recipe = procex.Recipe.load(sys.argv[1])
n = 0
for b in procex.{call}(recipe, sys.argv[2], jobs=2):
    n += b.status == "ok" and len(b.meshes) > 0
assert n == int(sys.argv[3]), n
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def peak_kb(call, footprints, n):
    r = subprocess.run([sys.executable, "-c", PEAK.format(call=call), str(SAMPLES / "city.pxg"), str(footprints),
                        str(n)], capture_output=True, text=True, env=os.environ)
    assert r.returncode == 0, r.stderr
    return int(r.stdout)


def test_peak_memory_does_not_follow_the_footprints(tmp_path):
    """batch() holds every building (16.5 KB a city building, BENCHMARKS); the
    iterator a window of them and 40 bytes a footprint of the spool's index."""
    files = {}
    for n in (2_000, 20_000):
        files[n] = tmp_path / f"{n}.geojson"
        subprocess.run([sys.executable, ROOT / "bench" / "batch_footprints.py", str(n), files[n]], check=True)
    small, large = (peak_kb("batch_iter", files[n], n) for n in (2_000, 20_000))
    print(f"batch_iter peak RSS: 2,000 footprints {small / 1024:.0f} MB, 20,000 {large / 1024:.0f} MB")
    # 18,000 more buildings held would be about 290 MB more.
    assert large - small < 20 * 1024, (small, large)


HELD = """
import sys
import procex
it = procex.batch_iter(procex.Recipe.load(sys.argv[1]), sys.argv[2], jobs=1)
assert len(it) == int(sys.argv[3]), len(it)
status = dict(line.split(":", 1) for line in open("/proc/self/status"))
print(int(status["VmHWM"].split()[0]))
"""


def test_what_is_held_a_footprint_is_a_few_dozen_bytes(tmp_path):
    """What the iterator keeps for each footprint it has not handed over, peak
    RSS once made: the spool's index (40 bytes) and its own (24), about 75
    bytes with the vectors' doubling (BENCHMARKS). It was about 190 while each
    footprint's item held two strings (88 bytes), unreserved: 19 MB of a 1M
    batch's memory then, for nothing but the few unreadable ones."""
    peaks = {}
    for n in (20_000, 100_000):
        path = tmp_path / f"{n}.geojson"
        subprocess.run([sys.executable, ROOT / "bench" / "batch_footprints.py", str(n), path], check=True)
        r = subprocess.run([sys.executable, "-c", HELD, str(SAMPLES / "city.pxg"), str(path), str(n)],
                           capture_output=True, text=True, env=os.environ)
        assert r.returncode == 0, r.stderr
        peaks[n] = int(r.stdout)
    per_footprint = (peaks[100_000] - peaks[20_000]) * 1024 / 80_000
    print(f"batch_iter before the first building: {peaks[20_000] / 1024:.0f} MB at 20,000 footprints, "
          f"{peaks[100_000] / 1024:.0f} MB at 100,000: {per_footprint:.0f} bytes a footprint")
    assert per_footprint < 120, peaks
