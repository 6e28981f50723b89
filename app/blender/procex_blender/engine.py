"""The procex module as the add-on uses it: one loaded Recipe per file.

The module comes bundled with the add-on (the zip the build makes holds the
procex extension beside these files), else from Python's path (cmake --install).
A Recipe keeps its result cache between evaluations, so a parameter change
recomputes only the nodes it reaches.
"""
import os

try:
    from . import procex  # noqa: F401  (bundled)
except ImportError:
    import procex  # noqa: F401

_recipes = {}


def recipe(path):
    """The loaded recipe for path (loaded once, then shared)."""
    path = os.path.abspath(path)
    r = _recipes.get(path)
    if r is None:
        r = _recipes[path] = procex.Recipe.load(path)
    return r


def as_saved(path):
    """The recipe with its file's own values, loaded anew: the shared one of
    recipe() carries the settings of the object evaluated last, which neither
    a new object's panel nor a batch should start from."""
    return procex.Recipe.load(os.path.abspath(path))


def forget():
    _recipes.clear()
