"""procex.pyi is generated beside the module from the module itself: every
public name has a stub, with its docstring, and the node type names are those
the registry declares."""
import ast
import pathlib

import procex


def stub():
    path = pathlib.Path(procex.__file__).with_name("procex.pyi")
    return path.read_text()


def test_stub_parses_and_covers_the_module():
    tree = ast.parse(stub())
    names = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    names |= {t.id for n in tree.body if isinstance(n, (ast.Assign, ast.AnnAssign))
              for t in (n.targets if isinstance(n, ast.Assign) else [n.target]) if isinstance(t, ast.Name)}
    public = {n for n in dir(procex) if not n.startswith("_")}
    assert public <= names, public - names


def test_stub_lists_every_node_type():
    text = stub()
    for name in procex.node_types():
        assert f'"{name}",' in text


def test_stub_signatures_and_docs():
    tree = ast.parse(stub())
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    recipe = {f.name: f for f in classes["Recipe"].body if isinstance(f, ast.FunctionDef)}
    assert [a.arg for a in recipe["evaluate"].args.args] == ["self", "footprint", "attributes"]
    assert ast.get_docstring(recipe["evaluate"])
    sweep = next(n for n in tree.body if isinstance(n, ast.FunctionDef) and n.name == "sweep")
    assert [a.arg for a in sweep.args.args] == ["loops", "angles", "profiles", "max_height"]
    assert "Mesh" in ast.unparse(sweep.returns)
    assert ast.get_docstring(classes["Mesh"])
