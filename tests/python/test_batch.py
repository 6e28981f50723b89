"""procex.batch: the 18 sample-block buildings as procex batch makes them
(samples/expected/city.json), the same for any number of threads, progress
reported, failures reported per building, and the GIL released."""
import json
import threading
import time

import numpy as np
import pytest

import procex
from conftest import SAMPLES, assert_matches, expected, summary

BLOCK = SAMPLES / "footprints" / "sample_block.geojson"


def city():
    return procex.Recipe.load(SAMPLES / "city.pxg")


def test_sample_block_matches_stored_summaries():
    want = expected("city")
    buildings = procex.batch(city(), BLOCK)
    assert len(buildings) == 18 and [b.index for b in buildings] == list(range(18))
    for b in buildings:
        assert b.status == "ok", b.reason
        assert all(m.building == b.id for m in b.meshes)
        assert_matches({**want["buildings"][b.id], "tolerance": want["tolerance"]}, summary(b.meshes), b.id)
    assert {b.id for b in buildings} == set(want["buildings"])


def test_threads_do_not_change_results():
    one = procex.batch(city(), BLOCK, jobs=1)
    two = procex.batch(city(), BLOCK, jobs=2)
    for a, b in zip(one, two):
        assert a.id == b.id
        np.testing.assert_array_equal(a.meshes[0].vertices, b.meshes[0].vertices)
        np.testing.assert_array_equal(a.meshes[0].face_indices, b.meshes[0].face_indices)


def test_progress_counts_up_to_total():
    seen = []
    procex.batch(city(), BLOCK, jobs=2, progress=lambda done, total: seen.append((done, total)))
    assert seen and seen[-1] == (18, 18)
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)


def test_exception_in_progress_stops_the_batch():
    def stop(done, total):
        raise KeyError("stop here")

    with pytest.raises(KeyError, match="stop here"):
        procex.batch(city(), BLOCK, jobs=1, progress=stop)


def test_features_as_dicts_and_a_bad_one_is_refused():
    collection = json.loads(BLOCK.read_text())
    collection["features"][3]["geometry"]["coordinates"] = "not coordinates"
    buildings = procex.batch(city(), collection)
    assert [b.status for b in buildings].count("ok") == 17
    bad = buildings[3]
    assert bad.status == "refused" and "coordinates" in bad.reason and bad.meshes == []


def test_failing_building_does_not_stop_others():
    square = [[0, 0], [10, 0], [10, 10], [0, 10]]
    bowtie = [[0, 0], [10, 10], [10, 0], [0, 10]]
    buildings = procex.batch(city(), [[square], [bowtie], [square]])
    assert [b.status for b in buildings] == ["ok", "failed", "ok"]
    assert "node" in buildings[1].reason and "Extrude" in buildings[1].reason


def test_recipe_without_footprint_input_is_refused():
    with pytest.raises(procex.RecipeError, match="graph input named 'footprint'"):
        procex.batch(procex.Recipe.load(SAMPLES / "house.pxg"), BLOCK)


def test_missing_file_raises_footprint_error(tmp_path):
    with pytest.raises(procex.FootprintError, match="nothing.geojson"):
        procex.batch(city(), tmp_path / "nothing.geojson")


def test_gil_is_released_while_buildings_evaluate():
    # Python code keeps running beside a batch: the counter thread gets the GIL
    # while the workers evaluate (a batch holding the GIL would starve it).
    block = json.loads(BLOCK.read_text())
    block["features"] = block["features"] * 20
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    t = threading.Thread(target=tick)
    t.start()
    start = time.monotonic()
    buildings = procex.batch(city(), block, jobs=2)
    end = time.monotonic()
    done.set()
    t.join()
    assert all(b.status == "ok" for b in buildings)
    assert sum(start <= x <= end for x in ticks) >= 10


def test_recipes_evaluate_concurrently_from_threads():
    r = procex.Recipe.load(SAMPLES / "house.pxg")
    results, errors = [], []

    def work(pitch):
        try:
            results.append((pitch, summary(r.evaluate(attributes={"pitch": pitch}))["max"][2]))
        except Exception as e:  # noqa: BLE001  (reported below)
            errors.append(e)

    threads = [threading.Thread(target=work, args=(p,)) for p in (25, 30, 35, 40, 25, 30, 35, 40)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    heights = {}
    for pitch, z in results:
        assert heights.setdefault(pitch, z) == z
    assert heights[25] > heights[30] > heights[35] > heights[40]  # pitch from the vertical: 25 is the steepest
