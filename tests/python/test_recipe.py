"""procex.Recipe: every sample evaluates to the summary the C++ sample test
stores (samples/expected), exposed parameters as their declarations say, and
a parameter change moves the mesh as it should."""
import shutil

import numpy as np
import pytest

import procex
from conftest import SAMPLES, assert_matches, expected, summary

NAMES = sorted(p.stem for p in SAMPLES.glob("*.pxg") if p.stem != "city")


def test_every_sample_is_tested():
    assert len(NAMES) >= 5 and "house" in NAMES


@pytest.mark.parametrize("name", NAMES)
def test_sample_matches_stored_summary(name):
    parts = procex.Recipe.load(SAMPLES / f"{name}.pxg").evaluate()
    assert_matches(expected(name), summary(parts), name)


def test_house_exposed_parameters_come_from_declarations():
    r = procex.Recipe.load(SAMPLES / "house.pxg")
    exposed = {p.name: p for p in r.exposed}
    assert set(exposed) == {"shape", "pitch"}
    pitch = exposed["pitch"]
    assert pitch.type == "float" and pitch.unit == "deg"
    assert pitch.min is not None and pitch.max is not None and pitch.min < pitch.value < pitch.max
    assert pitch.node_type and pitch.doc
    for p in exposed.values():  # the house exposes its nodes' parameters under their own names
        declared = {d.name: d for d in procex.node_types()[p.node_type].params}[p.name]
        assert p.default == declared.default and (p.min, p.max, p.unit) == (declared.min, declared.max, declared.unit)
    assert pitch.default != pitch.value  # the declaration's default, not the value the recipe sets
    shape = exposed["shape"]
    assert shape.type == "enum" and shape.value in shape.choices and len(shape.choices) >= 2
    assert r.get("pitch") == pitch.value
    assert [o for o in r.outputs] == ["mesh"]


def test_set_changes_the_mesh_and_back():
    r = procex.Recipe.load(SAMPLES / "house.pxg")
    base = summary(r.evaluate())
    pitch = r.get("pitch")
    r.set("pitch", pitch - 10)  # degrees from the vertical: a steeper roof
    steeper = summary(r.evaluate())
    assert steeper["faces"] == base["faces"]
    assert steeper["max"][2] > base["max"][2] + 0.5  # a steeper roof is higher
    assert steeper["volume"] > base["volume"]
    np.testing.assert_allclose(steeper["min"], base["min"])  # the plan does not move
    r.set("pitch", pitch)
    assert_matches(expected("house"), summary(r.evaluate()), "house after setting pitch back")


def test_setting_matches_cli_set(tmp_path):
    from conftest import cli

    r = procex.Recipe.load(SAMPLES / "house.pxg")
    r.set("shape", "rectangle")
    r.set("pitch", 40)
    py = summary(r.evaluate())
    code, out, err = cli("eval", SAMPLES / "house.pxg", "-o", tmp_path / "h.obj", "--set", "shape=rectangle",
                         "--set", "pitch=40")
    assert code == 0, err
    assert f"{py['faces']} faces" in out


def test_arrays_shapes_dtypes_and_views():
    (part,) = procex.Recipe.load(SAMPLES / "house.pxg").evaluate()
    v = part.vertices
    assert v.shape == (part.n_vertices, 3) and v.dtype == np.float64
    assert not v.flags.writeable
    assert np.shares_memory(v, part.vertices)  # a view of the mesh's storage, not a fresh copy each time
    assert part.face_offsets.shape == (part.n_faces + 1,) and part.face_offsets.dtype == np.int32
    assert part.face_offsets[0] == 0 and part.face_offsets[-1] == len(part.face_indices)
    assert np.all(np.diff(part.face_offsets) >= 3)
    assert part.face_indices.min() >= 0 and part.face_indices.max() < part.n_vertices
    assert part.face_tags.shape == (part.n_faces,) and part.face_tags.dtype == np.uint32
    assert part.face_tags.max() < len(part.tags)
    assert part.source_edges.shape == (part.n_faces,) and part.source_edges.dtype == np.int32
    assert part.face_kinds.shape == (part.n_faces,) and set(part.face_kinds) <= {0, 1, 2}
    # every edge of a closed 2-manifold is used once each way
    idx, off = part.face_indices, part.face_offsets
    halfedges = set()
    for f in range(part.n_faces):
        loop = idx[off[f]:off[f + 1]]
        for a, b in zip(loop, np.roll(loop, -1)):
            assert (a, b) not in halfedges
            halfedges.add((a, b))
    assert all((b, a) in halfedges for a, b in halfedges)


def test_every_array_is_a_view_owned_by_its_mesh():
    """No array is a copy made for Python: each is a read-only view whose base
    is the procex.Mesh holding the storage, the same memory on every read."""
    (part,) = procex.Recipe.load(SAMPLES / "house.pxg").evaluate()
    for name in ("vertices", "face_offsets", "face_indices", "face_tags", "source_edges", "face_kinds", "uvs", "normals"):
        a = getattr(part, name)
        assert a.base is part and not a.flags.owndata and not a.flags.writeable, name
        assert getattr(part, name).ctypes.data == a.ctypes.data, name


def test_arrays_outlive_the_mesh_and_recipe():
    v = procex.Recipe.load(SAMPLES / "house.pxg").evaluate()[0].vertices
    import gc

    gc.collect()
    assert np.isfinite(v).all() and v[:, 2].max() > 8


def test_placed_meshes_are_instances_with_matrices():
    (part,) = procex.Recipe.load(SAMPLES / "windows_grid.pxg").evaluate()
    assert len(part.placed) == 28
    names = {p.mesh.name for p in part.placed}
    assert names == {"window", "window_frame"}
    for placement in part.placed:
        mesh, matrix = placement
        assert matrix.shape == (4, 4)
        np.testing.assert_allclose(matrix[3], [0, 0, 0, 1])
        world = mesh.vertices @ matrix[:3, :3].T + matrix[:3, 3]
        lo, hi = part.vertices.min(axis=0) - 1, part.vertices.max(axis=0) + 1
        assert np.all(world >= lo) and np.all(world <= hi)  # on the building
    by_name = {}
    for p in part.placed:  # one mesh per name, shared by its placements
        by_name.setdefault(p.mesh.name, p.mesh.vertices.__array_interface__["data"][0])
        assert p.mesh.vertices.__array_interface__["data"][0] == by_name[p.mesh.name]


def test_footprint_as_feature_and_as_loops(samples):
    import json

    r = procex.Recipe.load(samples / "city.pxg")
    features = json.loads((samples / "footprints" / "sample_block.geojson").read_text())["features"]
    want = expected("city")
    for f in features[:3]:
        (part,) = r.evaluate(footprint=f)
        assert part.building == f["id"]
        got = summary([part])
        assert_matches({**want["buildings"][f["id"]], "tolerance": want["tolerance"]}, got, f["id"])
    square = [[0, 0], [10, 0], [10, 10], [0, 10]]
    (part,) = r.evaluate(footprint=[square])
    assert part.vertices[:, 0].min() == 0 and part.vertices[:, 0].max() == 10
    (geometry,) = r.evaluate(footprint={"type": "Polygon", "coordinates": [square + [square[0]]]})
    np.testing.assert_allclose(summary([geometry])["volume"], summary([part])["volume"])


def test_feature_properties_set_parameters_of_the_same_name():
    r = procex.Recipe.load(SAMPLES / "city.pxg")
    square = [[0, 0], [12, 0], [12, 12], [0, 12], [0, 0]]

    def height(building):
        feature = {"type": "Feature", "id": "b1", "properties": {"building": building},
                   "geometry": {"type": "Polygon", "coordinates": [square]}}
        (part,) = r.evaluate(footprint=feature)
        assert part.building == "b1"
        return part.vertices[:, 2].max()

    assert height("church") != height("house")


def test_attributes_apply_for_one_evaluation_only():
    r = procex.Recipe.load(SAMPLES / "house.pxg")
    steep = summary(r.evaluate(attributes={"pitch": r.get("pitch") - 10}))
    again = summary(r.evaluate())
    assert steep["max"][2] > again["max"][2]
    assert_matches(expected("house"), again, "house after a one-off attribute")


def test_node_types_document_their_declarations():
    types = procex.node_types()
    assert "Extrude" in types
    extrude = types["Extrude"]
    assert extrude.doc and "Extrude" in extrude.markdown
    assert extrude.outputs and all(p.name for p in extrude.params)
    for t in types.values():
        for p in t.params:
            if p.min is not None:
                assert p.value is None or p.min <= p.value


def test_a_change_recomputes_only_the_nodes_it_reaches():
    r = procex.Recipe.load(SAMPLES / "house.pxg")
    node = {p.name: p.node for p in r.exposed}
    r.evaluate()
    first = {path: outcome for path, _, outcome in r.last_evaluation}
    assert set(first.values()) == {"computed"} and {node["pitch"], node["shape"]} <= set(first)
    r.evaluate()
    assert [o for _, _, o in r.last_evaluation] == ["cache hit"]  # nothing changed: the output node's result is reused
    r.set("pitch", r.get("pitch") - 10)
    r.evaluate()
    after = {path: outcome for path, _, outcome in r.last_evaluation}
    assert after[node["pitch"]] == "computed"
    assert after[node["shape"]] == "cache hit"  # the footprint branch is not recomputed
    computed = {p for p, o in after.items() if o == "computed"}
    assert computed < set(first)


def test_placed_mesh_materials_and_own_uvs(tmp_path):
    """The sample door placed instead of the window: its .mtl's colours and
    texture (an absolute path inside the recipe's folder) and its face's own
    texture coordinates."""
    shutil.copytree(SAMPLES / "meshes", tmp_path / "meshes")
    recipe = (SAMPLES / "windows_grid.pxg").read_text().replace(
        '"file": "meshes/window_frame.obj"', '"file": "meshes/door_textured.obj"', 1)
    (tmp_path / "doors.pxg").write_text(recipe)
    (part,) = procex.Recipe.load(tmp_path / "doors.pxg").evaluate()
    assert part.materials == {}
    door = next(p.mesh for p in part.placed if p.mesh.name == "window")  # the node's `name`
    plain = {"roughness": 0.9, "metallic": 0.0, "tile_size": 1.0}
    assert door.materials == {
        "door": {"colour": (1.0, 1.0, 1.0), "texture": str((tmp_path / "meshes" / "door_planks.png").resolve()), **plain},
        "door_frame": {"colour": (0.2, 0.25, 0.3), "texture": None, **plain},
    }
    front = list(door.face_tags).index(door.tags.index("door"))
    corners = door.uvs[door.face_offsets[front]:door.face_offsets[front + 1]]
    assert sorted(map(tuple, corners)) == [(0, 0), (0, 1), (1, 0), (1, 1)]


def test_material_nodes_give_each_tag_its_look():
    """samples/textured_house.pxg: each Material node's colour, roughness,
    metalness, texture (an absolute path in the recipe's folder) and tile size,
    on the building's mesh; a tag without one (the base) has none."""
    (part,) = procex.Recipe.load(SAMPLES / "textured_house.pxg").evaluate()
    brick = str((SAMPLES / "textures" / "brick.png").resolve())
    assert part.materials["wall"] == {"colour": (1.0, 1.0, 1.0), "roughness": 0.85, "metallic": 0.0,
                                      "texture": brick, "tile_size": 0.8}
    assert part.materials["gable"] == part.materials["wall"]
    assert part.materials["roof"]["tile_size"] == 1.2
    assert part.materials["soffit"] == {"colour": (0.9, 0.9, 0.85), "roughness": 0.5, "metallic": 0.0,
                                        "texture": None, "tile_size": 1.0}
    assert set(part.materials) == {"wall", "gable", "roof", "soffit"}
    assert "base" in part.tags


def test_exposed_for_a_footprint_as_its_properties_bind_them():
    r = procex.Recipe.load(SAMPLES / "city.pxg")
    square = [[0, 0], [12, 0], [12, 12], [0, 12], [0, 0]]

    def feature(properties):
        return {"type": "Feature", "id": "b1", "properties": properties,
                "geometry": {"type": "Polygon", "coordinates": [square]}}

    own = {p.name: p for p in r.exposed}["building"]
    assert own.property is None
    bound = {p.name: p for p in r.exposed_for(feature({"Building": "church", "height": 9}))}["building"]
    assert (bound.value, bound.property) == ("church", "Building")  # named as procex batch matches names
    assert {p.name: p for p in r.exposed_for(feature({}))}["building"].value == own.value
    assert r.get("building") == own.value  # the recipe itself is left as it was
    with pytest.raises(procex.FootprintError) as e:  # as evaluate() refuses it
        r.exposed_for(feature({"building": "church", "BUILDING": "house"}))
    assert e.value.feature == "b1" and "both set 'building'" in str(e.value)
