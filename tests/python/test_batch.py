"""procex.batch: the 18 sample-block buildings as procex batch makes them
(samples/expected/city.json), the same for any number of threads, progress
reported, failures reported per building, and the GIL released."""
import json
import subprocess
import sys
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


def test_a_placed_mesh_is_one_object_over_the_batch():
    # Every building places the one window file: wrapped once (in the workers), one procex.Mesh.
    buildings = procex.batch(city(), BLOCK, jobs=2)
    windows = [p.mesh for b in buildings for m in b.meshes for p in m.placed if p.mesh.name == "window"]
    assert len(windows) > len(buildings)
    assert all(w is windows[0] for w in windows)
    assert windows[0].face_offsets[-1] == len(windows[0].face_indices) > 0


def test_a_building_evaluates_again_from_its_feature():
    """Building.feature is the feature as the batch evaluated it, party and
    street edges included: evaluating it alone (as the Blender add-on does
    after a parameter change) makes the same mesh. Without the party edges
    the terraced buildings of the block come out with other faces."""
    r = city()
    buildings = procex.batch(r, BLOCK)
    file_features = {f["id"]: f for f in json.loads(BLOCK.read_text())["features"]}
    with_party_walls = 0
    for b in buildings:
        f = b.feature
        assert f["type"] == "Feature" and f["id"] == b.id
        for key, value in file_features[b.id]["properties"].items():
            assert f["properties"][key] == value, (b.id, key)
        with_party_walls += bool(f["properties"]["party_edges"])
        (again,) = r.evaluate(footprint=f)
        (mesh,) = b.meshes
        np.testing.assert_array_equal(again.vertices, mesh.vertices, err_msg=b.id)
        np.testing.assert_array_equal(again.face_indices, mesh.face_indices, err_msg=b.id)
        assert [again.tags[t] for t in again.face_tags] == [mesh.tags[t] for t in mesh.face_tags], b.id
    assert with_party_walls >= 5  # the block's terraces: the check above sees their party walls


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
    assert bad.status == "refused" and "coordinates" in bad.reason and bad.meshes == [] and bad.feature is None


def test_failing_building_does_not_stop_others():
    square = [[0, 0], [10, 0], [10, 10], [0, 10]]
    bowtie = [[0, 0], [10, 10], [10, 0], [0, 10]]
    buildings = procex.batch(city(), [[square], [bowtie], [square]])
    assert [b.status for b in buildings] == ["ok", "refused", "ok"]  # as procex roof calls it
    assert "intersects itself" in buildings[1].reason


def test_recipe_without_footprint_input_is_refused():
    with pytest.raises(procex.RecipeError, match="graph input named 'footprint'"):
        procex.batch(procex.Recipe.load(SAMPLES / "house.pxg"), BLOCK)


def test_missing_file_raises_footprint_error(tmp_path):
    with pytest.raises(procex.FootprintError, match="nothing.geojson"):
        procex.batch(city(), tmp_path / "nothing.geojson")


def test_gil_is_released_while_buildings_evaluate():
    # Python code keeps running beside a batch. With the interpreter's forced
    # switching turned off, a thread gets the GIL only when its holder lets go
    # of it; the progress callback never does, so the counting thread can
    # advance between two reports only if the batch releases the GIL while its
    # workers evaluate. It counts events, not time: the outcome does not depend
    # on the machine's speed.
    block = json.loads(BLOCK.read_text())
    block["features"] = block["features"] * 40
    count = [0]
    done = threading.Event()

    def spin():
        while not done.is_set():
            count[0] += 1
            time.sleep(0)  # lets go of the GIL, so the batch can always take it back

    reports = []
    recipe = city()
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1000.0)
    t = threading.Thread(target=spin)
    t.start()
    try:
        buildings = procex.batch(recipe, block, jobs=2, progress=lambda d, n: reports.append((d, count[0])))
    finally:
        done.set()
        t.join()
        sys.setswitchinterval(interval)
    assert all(b.status == "ok" for b in buildings)
    assert len(reports) >= 2 and reports[-1][0] == len(buildings)
    assert reports[-1][1] > reports[0][1], "no Python ran while the buildings evaluated"


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


def test_any_footprint_file_procex_batch_reads(tmp_path):
    # The sample block as a Shapefile and a GeoPackage, written by GDAL's ogr2ogr:
    # the same buildings as from the GeoJSON.
    want = {b.id: b.meshes[0].vertices.shape for b in procex.batch(city(), BLOCK)}
    for name in ("block.shp", "block.gpkg"):
        subprocess.run(["ogr2ogr", "-a_srs", "EPSG:32632", str(tmp_path / name), str(BLOCK)], check=True)  # metres, as the GeoJSON
        buildings = procex.batch(city(), tmp_path / name)
        assert all(b.status == "ok" for b in buildings), name
        assert {b.id: b.meshes[0].vertices.shape for b in buildings} == want, name
        # the feature's attributes as GDAL read them (a Shapefile cuts field names to 10 characters)
        properties = buildings[0].feature["properties"]
        assert properties["building"] == "yes" and properties["area_m2"] == 304.86, (name, properties)
