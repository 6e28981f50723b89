"""Writes procex.pyi beside the built procex module, from the module itself.

Every signature and docstring comes from the bindings (pybind11 puts the C++
signature on each docstring's first line), the node type names from the node
registry (procex.node_types()), so the stubs cannot drift from the module.
Usage: make_stubs.py FOLDER (the folder holding the built module).
"""
import importlib
import os
import re
import sys
import tempfile

TYPES = [
    (re.compile(r"\bprocex\."), ""),
    (re.compile(r"numpy\.ndarray\[[^\]]*\]"), "numpy.ndarray"),
    (re.compile(r"\bList\["), "list["),
    (re.compile(r"\bDict\["), "dict["),
    (re.compile(r"\bTuple\["), "tuple["),
    (re.compile(r"\bobject\b"), "typing.Any"),
    (re.compile(r"\bos\.PathLike\b"), "str | os.PathLike[str]"),
]

# Attributes the exception classes carry (errors.cc sets them on the instance).
ERROR_ATTRIBUTES = {
    "RecipeError": ["file: str"],
    "ParameterError": ["name: str"],
    "FootprintError": ["loop: int", "vertex: int"],
    "EvaluationError": ["file: str", "diagnostics: list[tuple[str, str, str, str]]"],
    "SweepError": ["height: float", "edges: list[int]"],
}


def python_type(text):
    for pattern, replacement in TYPES:
        text = pattern.sub(replacement, text)
    return text


def doc_lines(doc, indent):
    doc = (doc or "").strip().replace('"""', "'''")
    if not doc:
        return []
    pad = " " * indent
    body = doc.splitlines()
    return [pad + '"""' + body[0]] + [pad + line if line else "" for line in body[1:]] + [pad + '"""']


def split_signature(obj):
    """(signature, rest of the docstring) from a pybind11 docstring."""
    doc = obj.__doc__ or ""
    first, _, rest = doc.strip().partition("\n")
    return first, rest.strip()


def function(name, obj, indent, static=False):
    first, rest = split_signature(obj)
    match = re.match(r"\w+(\(.*\))( -> (.*))?$", first)
    params, returns = (match.group(1), match.group(3) or "None") if match else ("(*args, **kwargs)", "typing.Any")
    params = re.sub(r"\bself: [\w.]+", "self", params)
    pad = " " * indent
    out = [pad + "@staticmethod"] if static else []
    out.append(f"{pad}def {name}{python_type(params)} -> {python_type(returns)}:")
    out += doc_lines(rest, indent + 4) or []
    out.append(pad + "    ...")
    return out


def prop(name, obj, indent):
    first, rest = split_signature(obj.fget)
    match = re.match(r"\(.*\) -> (.*)$", first)
    annotation = python_type(match.group(1)) if match else "typing.Any"
    pad = " " * indent
    return [f"{pad}@property", f"{pad}def {name}(self) -> {annotation}:"] + doc_lines(rest, indent + 4) + [pad + "    ..."]


def klass(name, cls):
    out = [f"class {name}:"] + doc_lines(cls.__doc__, 4)
    for attr, value in sorted(vars(cls).items()):
        if attr.startswith("__") and attr not in ("__iter__", "__repr__"):
            continue
        if isinstance(value, property):
            out += prop(attr, value, 4)
        elif isinstance(value, staticmethod):
            out += function(attr, value.__func__, 4, static=True)
        elif callable(value):
            out += function(attr, value, 4)
    return out + [""]


def main(folder):
    sys.path.insert(0, folder)
    procex = importlib.import_module("procex")
    out = ['"""' + procex.__doc__.strip() + '"""', "", "import os", "import typing", "", "import numpy", ""]
    names = sorted(procex.node_types())
    out += ["# The node types a recipe may use (procex.node_types()).", "NodeTypeName = typing.Literal["]
    out += [f'    "{n}",' for n in names] + ["]", "", "__version__: str", ""]
    out += ["class Error(Exception):"] + doc_lines(procex.Error.__doc__, 4) + [""]
    for name, value in sorted(vars(procex).items()):
        if isinstance(value, type) and issubclass(value, procex.Error) and value is not procex.Error:
            out += [f"class {name}(Error):"] + doc_lines(value.__doc__, 4)
            out += ["    " + a for a in ERROR_ATTRIBUTES.get(name, [])] + [""]
    for name, value in sorted(vars(procex).items()):
        if name.startswith("_") or (isinstance(value, type) and issubclass(value, BaseException)):
            continue
        if isinstance(value, type):
            out += klass(name, value)
        elif callable(value):
            out += function(name, value, 0) + [""]
    text = "\n".join(out).rstrip() + "\n"
    text = text.replace("-> dict:", "-> dict[str, NodeType]:")
    # Written atomically: a half-written stub would mislead editors.
    fd, tmp = tempfile.mkstemp(dir=folder, suffix=".pyi.tmp")
    with os.fdopen(fd, "w") as f:
        f.write(text)
    os.replace(tmp, os.path.join(folder, "procex.pyi"))


if __name__ == "__main__":
    main(sys.argv[1])
