"""procex.Mesh's texture coordinates and normals: the arrays' shapes and
dtypes, and their values against what they must be, computed here from the
vertices alone (not from procex's own frames): unit normals perpendicular to
every edge of their face and pointing out; UVs in metres (each face laid flat
without stretching); on walls v is the height and u runs round the footprint;
the same numbers as the OBJ file the command line writes."""
import numpy as np
import pytest

import procex
from conftest import SAMPLES, cli


def faces(part):
    off = part.face_offsets
    for f in range(part.n_faces):
        yield f, slice(off[f], off[f + 1])


def newell(pts):
    """Twice the area vector of a planar polygon (the sum of its edges' cross products)."""
    return np.cross(pts, np.roll(pts, -1, axis=0)).sum(axis=0)


@pytest.fixture(scope="module")
def house():
    (part,) = procex.Recipe.load(SAMPLES / "house.pxg").evaluate()
    return part


def test_shapes_dtypes_and_views(house):
    uvs, normals = house.uvs, house.normals
    assert uvs.shape == (len(house.face_indices), 2) and uvs.dtype == np.float64
    assert normals.shape == (house.n_faces, 3) and normals.dtype == np.float64
    assert not uvs.flags.writeable and not normals.flags.writeable
    # made once, then views of the same storage
    assert np.shares_memory(uvs, house.uvs) and np.shares_memory(normals, house.normals)


def test_normals_are_unit_perpendicular_to_their_face_and_point_out(house):
    v, idx = house.vertices, house.face_indices
    np.testing.assert_allclose(np.linalg.norm(house.normals, axis=1), 1.0, atol=1e-12)
    volume_flux = 0.0
    for f, c in faces(house):
        pts = v[idx[c]]
        n = house.normals[f]
        edges = np.roll(pts, -1, axis=0) - pts
        np.testing.assert_allclose(edges @ n, 0.0, atol=1e-9, err_msg=f"face {f} edges off the normal's plane")
        area = newell(pts)
        assert n @ area > 0, f"face {f}: normal against the corners' winding"
        volume_flux += (pts.mean(axis=0) @ n) * np.linalg.norm(area) / 6.0
    # divergence theorem: sum of (centroid . n) * area / 3 is the volume, positive for outward normals
    assert volume_flux > 0


def test_uvs_are_metres_without_stretch(house):
    v, idx = house.vertices, house.face_indices
    for f, c in faces(house):
        pts, uv = v[idx[c]], house.uvs[c]
        for a in range(len(pts)):
            for b in range(a + 1, len(pts)):
                assert np.linalg.norm(uv[b] - uv[a]) == pytest.approx(np.linalg.norm(pts[b] - pts[a]), abs=1e-9), \
                    f"face {f}: corners {a} and {b} are not as far apart in UV as on the face"
        # (u, v, normal) right-handed: the texture is not mirrored seen from outside
        if len(pts) >= 3:
            uv_area = np.cross(uv, np.roll(uv, -1, axis=0)).sum() * 0.5
            assert uv_area > 0, f"face {f} is mirrored in UV"


def test_walls_v_is_height_and_u_runs_round_the_footprint(house):
    v, idx = house.vertices, house.face_indices
    wall = house.tags.index("wall")
    base = house.tags.index("base")
    (base_face,) = [f for f in range(house.n_faces) if house.face_tags[f] == base]
    off = house.face_offsets
    plan = v[idx[off[base_face]:off[base_face + 1]], :2]
    perimeter = np.linalg.norm(np.roll(plan, -1, axis=0) - plan, axis=1).sum()
    spans = []
    for f, c in faces(house):
        if house.face_tags[f] != wall:
            continue
        pts, uv = v[idx[c]], house.uvs[c]
        np.testing.assert_allclose(uv[:, 1], pts[:, 2], atol=1e-9, err_msg=f"wall {f}: v is not the height")
        bottom = pts[pts[:, 2] == pts[:, 2].min()]
        edge_length = np.linalg.norm(bottom[:, :2].max(axis=0) - bottom[:, :2].min(axis=0))
        span = uv[:, 0].max() - uv[:, 0].min()
        assert span == pytest.approx(edge_length, abs=1e-9), f"wall {f}: u span {span} != its edge {edge_length}"
        spans.append((uv[:, 0].min(), uv[:, 0].max()))
    # the walls' u intervals tile [0, perimeter] end to end: u runs on across corners
    spans.sort()
    assert spans[0][0] == pytest.approx(0.0, abs=1e-9)
    for (_, end), (start, _) in zip(spans, spans[1:]):
        assert start == pytest.approx(end, abs=1e-9)
    assert spans[-1][1] == pytest.approx(perimeter, abs=1e-9)


def test_placed_meshes_carry_them_too():
    (part,) = procex.Recipe.load(SAMPLES / "windows_grid.pxg").evaluate()
    meshes = {id(p.mesh): p.mesh for p in part.placed}
    assert meshes
    for m in meshes.values():
        assert m.uvs.shape == (len(m.face_indices), 2) and m.normals.shape == (m.n_faces, 3)
        np.testing.assert_allclose(np.linalg.norm(m.normals, axis=1), 1.0, atol=1e-12)


def test_same_numbers_as_the_obj_file(tmp_path, house):
    """procex eval -o house.obj --up z writes the same vt and vn (core's surface_attributes, shared)."""
    code, _, err = cli("eval", SAMPLES / "house.pxg", "-o", tmp_path / "house.obj", "--up", "z")
    assert code == 0, err
    vt, vn, obj_faces = [], [], {}
    for line in (tmp_path / "house.obj").read_text().splitlines():
        words = line.split()
        if not words:
            continue
        if words[0] == "vt":
            vt.append([float(x) for x in words[1:3]])
        elif words[0] == "vn":
            vn.append([float(x) for x in words[1:4]])
        elif words[0] == "f":
            corners = [tuple(int(i) - 1 for i in w.split("/")) for w in words[1:]]
            obj_faces[tuple(c[0] for c in corners)] = corners
    assert len(obj_faces) == house.n_faces
    for f, c in faces(house):
        corners = obj_faces[tuple(house.face_indices[c])]
        np.testing.assert_allclose(house.uvs[c], [vt[k[1]] for k in corners], atol=1e-12)
        np.testing.assert_allclose(house.normals[f], vn[corners[0][2]], atol=1e-12)
