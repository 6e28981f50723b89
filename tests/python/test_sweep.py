"""procex.sweep: the engine alone on plain loops, checked against closed-form
volumes of hipped roofs."""
import numpy as np
import pytest

import procex
from conftest import summary

RECT = [[0, 0], [10, 0], [10, 6], [0, 6]]  # 10 m x 6 m, counter-clockwise


def test_hipped_roof_at_45_degrees():
    m = procex.sweep([RECT])
    s = summary([m])
    # a hipped roof over a x b (a >= b) at 45 degrees rises b/2 and holds b^2 (3a - b) / 12
    assert s["max"][2] == pytest.approx(3.0)
    assert s["volume"] == pytest.approx(36 * (30 - 6) / 12)
    assert s["faces_per_tag"] == {"base": 1, "roof": 4}
    assert sorted(set(m.source_edges)) == [-1, 0, 1, 2, 3]


def test_per_edge_angles_make_gables():
    m = procex.sweep([RECT], angles=[[45, 0, 45, 0]])  # the short sides stand vertical: a gable roof
    s = summary([m])
    assert s["max"][2] == pytest.approx(3.0)
    assert s["volume"] == pytest.approx(6 * 3 / 2 * 10)  # a triangular prism


def test_profile_walls_then_roof():
    wall_roof = {"points": [[0, 0], [0, 3], [-3, 6]], "tags": ["wall", "roof"], "name": "house"}
    s = summary([procex.sweep([RECT], profiles=wall_roof)])
    assert s["max"][2] == pytest.approx(6.0)
    assert s["volume"] == pytest.approx(10 * 6 * 3 + 72)
    assert s["faces_per_tag"] == {"base": 1, "wall": 4, "roof": 4}


def test_max_height_caps():
    m = procex.sweep([RECT], max_height=1.0)
    s = summary([m])
    assert s["max"][2] == pytest.approx(1.0)
    assert 2 in set(m.face_kinds)  # a cap face
    # a frustum of the hipped roof: the 10 x 6 base shrinks by 1 m each side per metre up
    assert s["volume"] == pytest.approx((60 + 8 * 4 + np.sqrt(60 * 32)) / 3, rel=0.02)


def test_hole_is_a_courtyard():
    outer = [[0, 0], [20, 0], [20, 20], [0, 20]]
    hole = [[5, 5], [5, 15], [15, 15], [15, 5]]  # clockwise
    m = procex.sweep([outer, hole], angles=0, max_height=4)
    assert summary([m])["volume"] == pytest.approx((400 - 100) * 4)


def test_numpy_loops():
    m = procex.sweep([np.array(RECT, dtype=np.float32)])
    assert summary([m])["volume"] == pytest.approx(72)


def test_self_intersecting_loop_raises_footprint_error():
    bowtie = [[0, 0], [10, 10], [10, 0], [0, 10]]
    with pytest.raises(procex.FootprintError) as e:
        procex.sweep([bowtie])
    assert e.value.loop == 0
    assert isinstance(e.value, procex.Error)


def test_wrong_angle_count_names_the_loop():
    with pytest.raises(procex.FootprintError, match="loop 0 has 4 edges, given 3"):
        procex.sweep([RECT], angles=[[45, 45, 45]])


def test_bad_points_raise():
    with pytest.raises(procex.FootprintError, match=r"loop 0: expected an \(n, 2\) array"):
        procex.sweep([[[0, 0, 0], [1, 0, 0], [1, 1, 0]]])
    with pytest.raises(procex.FootprintError):
        procex.sweep([[[0, 0], [float("nan"), 0], [1, 1]]])
