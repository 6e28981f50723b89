"""Shared by the procex module's tests: where the samples are, the CLI to
compare with, and a MeshSummary computed from the NumPy arrays alone."""
import collections
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "samples"


@pytest.fixture
def samples():
    return SAMPLES


def cli(*args):
    """Runs the procex command line: (exit code, stdout, stderr)."""
    r = subprocess.run([os.environ["PROCEX_CLI"], *map(str, args)], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def summary(parts):
    """What nodes/support/mesh_summary.cc computes, from the arrays: counts,
    faces per tag, bounds, volume by the divergence theorem over face fans,
    placed meshes per name."""
    faces_per_tag = collections.Counter()
    placed = collections.Counter()
    lo, hi = np.full(3, np.inf), np.full(3, -np.inf)
    volume = 0.0
    for p in parts:
        v = p.vertices
        lo, hi = np.minimum(lo, v.min(axis=0)), np.maximum(hi, v.max(axis=0))
        faces_per_tag.update(p.tags[t] for t in p.face_tags)
        off, idx = p.face_offsets, p.face_indices
        for f in range(p.n_faces):
            pts = v[idx[off[f]:off[f + 1]]]
            volume += np.einsum("ij,ij->i", np.broadcast_to(pts[0], pts[1:-1].shape),
                                np.cross(pts[1:-1], pts[2:])).sum() / 6.0
        placed.update(pl.mesh.name for pl in p.placed)
    return {"meshes": len(parts), "faces": sum(p.n_faces for p in parts), "faces_per_tag": dict(faces_per_tag),
            "min": lo, "max": hi, "volume": volume, "placed": dict(placed)}


def expected(name):
    return json.loads((SAMPLES / "expected" / f"{name}.json").read_text())


def assert_matches(want, got, what):
    """Compares with a stored summary (samples/expected) within its stored tolerance."""
    length, volume = want["tolerance"]["length"], want["tolerance"]["volume_relative"]
    if "meshes" in want:
        assert got["meshes"] == want["meshes"], what
        assert got["faces"] == want["faces"], what
    assert got["faces_per_tag"] == want["faces_per_tag"], what
    assert got["placed"] == want.get("placed", {}), what
    np.testing.assert_allclose(got["min"], want["bounds"]["min"], rtol=0, atol=length, err_msg=what)
    np.testing.assert_allclose(got["max"], want["bounds"]["max"], rtol=0, atol=length, err_msg=what)
    assert abs(got["volume"] - want["volume"]) <= volume * abs(want["volume"]), what
