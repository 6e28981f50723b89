"""Errors arrive as procex.Error subclasses carrying what the command line
prints for the same problem."""
import json

import pytest

import procex
from conftest import SAMPLES, cli


def test_unreadable_recipe_names_file_and_line(tmp_path):
    bad = tmp_path / "bad.pxg"
    bad.write_text('{"format": "procex-graph", "version": 2,\n "nodes": [\n')
    with pytest.raises(procex.RecipeError) as e:
        procex.Recipe.load(bad)
    code, _, err = cli("eval", bad, "-o", tmp_path / "x.obj")
    assert code == 2
    assert str(e.value) == err.strip()
    assert "line" in str(e.value) and e.value.file == str(bad)


def test_missing_recipe(tmp_path):
    with pytest.raises(procex.RecipeError, match="nothing.pxg"):
        procex.Recipe.load(tmp_path / "nothing.pxg")


def test_out_of_range_parameter_says_what_cli_says(tmp_path):
    r = procex.Recipe.load(SAMPLES / "house.pxg")
    with pytest.raises(procex.ParameterError) as e:
        r.set("pitch", 500)
    code, _, err = cli("eval", SAMPLES / "house.pxg", "-o", tmp_path / "x.obj", "--set", "pitch=500")
    assert code == 2
    cli_reason = err.strip().split(": ", 1)[1]  # after "--set pitch=500"
    assert str(e.value).endswith(cli_reason)
    assert e.value.name == "pitch"
    assert r.get("pitch") != 500


def test_unknown_parameter_and_bad_choice():
    r = procex.Recipe.load(SAMPLES / "house.pxg")
    with pytest.raises(procex.ParameterError, match="no exposed parameter or input named 'pich'"):
        r.set("pich", 30)
    with pytest.raises(procex.ParameterError, match="shape"):
        r.set("shape", "dodecahedron")
    with pytest.raises(procex.ParameterError):
        r.get("pich")


def test_failed_evaluation_carries_node_diagnostics(tmp_path):
    r = procex.Recipe.load(SAMPLES / "city.pxg")  # its footprint input has no default
    with pytest.raises(procex.EvaluationError) as e:
        r.evaluate()
    code, _, err = cli("eval", SAMPLES / "city.pxg", "-o", tmp_path / "x.obj")
    assert code == 1
    for line in str(e.value).splitlines():
        assert line in err.splitlines()
    assert e.value.diagnostics and all(d[0] in ("error", "warning") for d in e.value.diagnostics)
    assert any(d[0] == "error" and d[1] and d[2] for d in e.value.diagnostics)  # node path and type


def test_bad_footprint_dict():
    r = procex.Recipe.load(SAMPLES / "city.pxg")
    with pytest.raises(procex.FootprintError, match="not type 'Point'"):
        r.evaluate(footprint={"type": "Point", "coordinates": [0, 0]})
    with pytest.raises(procex.FootprintError, match="footprint"):
        r.evaluate(footprint={"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
                                                                               "coordinates": [[[0, 0], [1]]]}})


def test_refused_feature_names_recipe_and_feature_as_the_cli(tmp_path):
    bowtie = {"type": "Feature", "id": "b7", "properties": {},
              "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 10], [10, 0], [0, 10], [0, 0]]]}}
    r = procex.Recipe.load(SAMPLES / "city.pxg")
    with pytest.raises(procex.FootprintError) as e:
        r.evaluate(footprint=bowtie)
    assert e.value.feature == "b7" and e.value.file == str(SAMPLES / "city.pxg")
    footprints = tmp_path / "bowtie.geojson"
    footprints.write_text(json.dumps({"type": "FeatureCollection", "features": [bowtie]}))
    code, _, err = cli("eval", SAMPLES / "city.pxg", "--footprints", footprints, "--feature", "b7", "-o", tmp_path / "x.obj")
    assert code == 2
    reason = err.strip().split("refused: ", 1)[1]  # after "procex eval: bowtie.geojson: feature b7: refused: "
    assert str(e.value).endswith(f"feature b7: {reason}") and "intersects itself" in reason
