"""samples/city.pxg over samples/footprints/terrace.geojson, checked on the
geometry procex.batch returns: each house is as many floors high as its
building:levels, each floor as high as its floor_height, every wall that is neither shared nor on a street has one
row of windows per floor at the floor heights, and each street-facing wall a
door on the ground floor, its sill at ground level, with windows above;
street lines come from the footprint file and from batch(streets=...)."""
import collections
import json

import numpy as np
import pytest

import procex
from conftest import SAMPLES

TERRACE = SAMPLES / "footprints" / "terrace.geojson"
EAST_STREET = SAMPLES / "footprints" / "terrace_east_street.geojson"
FLOOR = 3.0  # city.pxg's floor height (Levels, Facade Split) when a feature gives none

# terrace.geojson: three 10 x 12 m houses in a row along a street to the south (edge 0 of
# each); a lane behind the first (its edge 2); neighbours share edges 1 and 3.
STREET = {"a": {0, 2}, "b": {0}, "c": {0}}
PARTY = {"a": {1}, "b": {1, 3}, "c": {3}}


def city():
    return procex.Recipe.load(SAMPLES / "city.pxg")


def terrace(levels):
    collection = json.loads(TERRACE.read_text())
    for f in collection["features"]:
        if f["id"] in levels:
            f["properties"]["building:levels"] = levels[f["id"]]
    return collection


def world_z(placement):
    """Lowest and highest height of a placed mesh in the building's frame."""
    v = placement.mesh.vertices
    z = (np.c_[v, np.ones(len(v))] @ placement.matrix.T)[:, 2]
    return z.min(), z.max()


def placed_by_edge(building, name):
    out = collections.defaultdict(list)
    for p in building.meshes[0].placed:
        if p.mesh.name == name:
            out[p.source_edge].append(world_z(p))
    return out


def wall_top(building):
    m = building.meshes[0]
    wall = m.tags.index("wall")
    idx = m.face_indices
    tops = [m.vertices[idx[m.face_offsets[f]:m.face_offsets[f + 1]]][:, 2].max()
            for f in range(m.n_faces) if m.face_tags[f] == wall]
    return max(tops)


def test_floors_windows_and_doors_follow_levels_and_streets():
    levels = {"a": 2, "b": 3, "c": 5}
    buildings = procex.batch(city(), terrace(levels))
    assert [b.id for b in buildings] == ["a", "b", "c"]
    for b in buildings:
        assert b.status == "ok", b.reason
        n = levels[b.id]
        assert wall_top(b) == pytest.approx(n * FLOOR, abs=1e-9), b.id
        windows, doors = placed_by_edge(b, "window"), placed_by_edge(b, "door")
        assert set(doors) == STREET[b.id], b.id
        assert not (set(windows) & PARTY[b.id]), b.id  # party walls stay blank
        for edge in range(4):
            if edge in PARTY[b.id]:
                continue
            rows = sorted({round(lo, 6) for lo, _ in windows[edge]})
            floors = [int(z // FLOOR) for z in rows]
            street = edge in STREET[b.id]
            # One row per level, one per floor, each within its floor; a street wall's ground floor has the door.
            assert floors == list(range(1 if street else 0, n)), (b.id, edge, rows)
            assert all(hi < (int(lo // FLOOR) + 1) * FLOOR for lo, hi in windows[edge]), (b.id, edge)
            assert len({round(z - f * FLOOR, 6) for z, f in zip(rows, floors)}) == 1  # the same sill on every floor
            if street:
                assert len(doors[edge]) == 1, (b.id, edge)  # one door, in the middle of the wall
                lo, hi = doors[edge][0]
                assert lo == pytest.approx(0.0, abs=1e-9) and hi == pytest.approx(2.1, abs=1e-9), (b.id, edge)


def test_floor_heights_from_the_features():
    # The recipe's one floor height (the feature's floor_height) drives Levels and the three
    # Facade Splits: each house's walls, window rows and door follow its own.
    levels, heights = {"a": 2, "b": 3, "c": 4}, {"a": 2.8, "b": 3.5, "c": 4.25}
    collection = terrace(levels)
    for f in collection["features"]:
        if f["id"] in heights:
            f["properties"]["floor_height"] = heights[f["id"]]
    for b in procex.batch(city(), collection):
        assert b.status == "ok", b.reason
        n, h = levels[b.id], heights[b.id]
        assert wall_top(b) == pytest.approx(n * h, abs=1e-9), b.id
        windows, doors = placed_by_edge(b, "window"), placed_by_edge(b, "door")
        sill = None
        for edge in set(range(4)) - PARTY[b.id]:
            street = edge in STREET[b.id]
            rows = sorted({round(lo, 6) for lo, _ in windows[edge]})
            assert len(rows) == n - (1 if street else 0), (b.id, edge, rows)
            for floor, z in enumerate(rows, start=1 if street else 0):
                sill = z - floor * h if sill is None else sill
                assert z - floor * h == pytest.approx(sill, abs=1e-6), (b.id, edge, rows)  # one row per floor of h
            assert all(hi <= (int(lo // h) + 1) * h + 1e-9 for lo, hi in windows[edge]), (b.id, edge)
        for edge in STREET[b.id]:
            assert len(doors[edge]) == 1 and doors[edge][0][0] == pytest.approx(0.0, abs=1e-9), (b.id, edge)
    # From height over the floor height when building:levels is absent: 14 m of 3.5 m floors is 4.
    collection = terrace({})
    collection["features"][1]["properties"].update({"height": "14", "floor_height": 3.5})
    assert wall_top(procex.batch(city(), collection)[1]) == pytest.approx(4 * 3.5)


def test_levels_from_height_else_the_type():
    collection = terrace({})
    collection["features"][0]["properties"]["height"] = "12.4"  # OSM heights are text: round(12.4 / 3) = 4 floors
    buildings = procex.batch(city(), collection)
    assert [wall_top(b) for b in buildings] == pytest.approx([4 * FLOOR, 2 * FLOOR, 2 * FLOOR])  # houses: 2


def test_streets_file_adds_the_edges_facing_its_lines():
    levels = {"a": 2, "b": 2, "c": 2}
    alone = procex.batch(city(), terrace(levels))
    assert set(placed_by_edge(alone[2], "door")) == {0}
    # terrace_east_street.geojson: a street 12 m east of c faces its edge 1; one 25 m west of a is too far.
    for streets in (EAST_STREET, str(EAST_STREET), json.loads(EAST_STREET.read_text())):
        with_east = procex.batch(city(), terrace(levels), streets=streets)
        assert [set(placed_by_edge(b, "door")) for b in with_east] == [{0, 2}, {0}, {0, 1}]
    # The same as procex batch --streets gives for the file's path.
    by_path = procex.batch(city(), TERRACE, streets=EAST_STREET)
    assert [set(placed_by_edge(b, "door")) for b in by_path] == [{0, 2}, {0}, {0, 1}]


def test_unreadable_streets_are_a_footprint_error(tmp_path):
    with pytest.raises(procex.FootprintError, match="no_such_streets.geojson"):
        procex.batch(city(), TERRACE, streets=tmp_path / "no_such_streets.geojson")
    with pytest.raises(procex.FootprintError, match="streets must be"):
        procex.batch(city(), TERRACE, streets=42)
