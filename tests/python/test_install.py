"""The install step of scripts/setup.sh (cmake --install build --component
python): the module and its stubs land in the site folder the interpreter has
for the prefix (for /usr/local, Debian's /usr/local/lib/python3.X/dist-packages,
on python3's path), and import from there, without the build tree, to
evaluate the house as the build tree's module does."""
import os
import pathlib
import subprocess
import sys

from conftest import SAMPLES, expected


def test_installed_module_imports_from_the_prefix_site_folder(tmp_path):
    prefix = tmp_path / "prefix"
    subprocess.run([os.environ["CMAKE_COMMAND"], "--install", os.environ["PROCEX_BUILD_DIR"], "--component", "python",
                    "--prefix", prefix], check=True, capture_output=True)
    installed = sorted(p.relative_to(prefix) for p in prefix.rglob("*") if p.is_file())
    assert [p.name.split(".")[0] for p in installed] == ["procex", "procex"], installed
    assert {p.suffix for p in installed} == {".so", ".pyi"}
    folder = prefix / installed[0].parent
    # the folder python3 itself puts on its path for that prefix (site.getsitepackages)
    script = f"""
import site, sys
assert {str(folder)!r} in site.getsitepackages([{str(prefix)!r}]), site.getsitepackages([{str(prefix)!r}])
site.addsitedir({str(folder)!r})
# ahead of a procex installed for the whole system (scripts/setup.sh sample puts one in /usr/local)
sys.path.remove({str(folder)!r})
sys.path.insert(0, {str(folder)!r})
import procex
assert procex.__file__.startswith({str(folder)!r}), procex.__file__
(mesh,) = procex.Recipe.load({str(SAMPLES / "house.pxg")!r}).evaluate()
print(mesh.n_faces, mesh.vertices[:, 2].max())
"""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # not the build tree
    out = subprocess.run([sys.executable, "-c", script], env=env, check=True, capture_output=True, text=True).stdout
    faces, top = out.split()
    want = expected("house")
    assert int(faces) == want["faces"]
    assert abs(float(top) - want["bounds"]["max"][2]) <= want["tolerance"]["length"]
