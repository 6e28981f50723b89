"""What an object made from a recipe remembers: the recipe file, the feature
it was evaluated for (batch buildings), and the recipe's exposed parameters
with their ranges and units. Changing a parameter re-evaluates the recipe and
replaces the object's mesh in place."""
import json
import time

import bpy

from . import engine, mesh_data

_applying = False  # set while values are written by the add-on itself: no re-evaluation then
_enum_items = {}   # Blender needs the items of a dynamic enum kept alive


def _changed(self, context):
    if _applying:
        return
    obj = self.id_data
    try:
        evaluate(obj)
    except engine.procex.Error as e:
        obj.procex.error = str(e)


def _choices(self, context):
    key = self.choices
    if key not in _enum_items:
        _enum_items[key] = [(c, c, "") for c in json.loads(key or "[]")]
    return _enum_items[key]


class ProcexParameter(bpy.types.PropertyGroup):
    # name (from PropertyGroup): the exposed parameter's name
    kind: bpy.props.EnumProperty(items=[(k, k, "") for k in ("FLOAT", "INT", "BOOL", "ENUM", "STRING", "JSON")])
    float_value: bpy.props.FloatProperty(update=_changed, precision=3)
    int_value: bpy.props.IntProperty(update=_changed)
    bool_value: bpy.props.BoolProperty(update=_changed)
    enum_value: bpy.props.EnumProperty(items=_choices, update=_changed)
    text_value: bpy.props.StringProperty(update=_changed)  # strings, and lists as JSON
    choices: bpy.props.StringProperty()  # JSON list, enums only
    bounds: bpy.props.StringProperty()  # JSON [min, max], null where unbounded: exact, unlike a float property
    unit: bpy.props.StringProperty()
    doc: bpy.props.StringProperty()
    # The footprint's property that set it (batch buildings): it would win over set(), so the
    # panel's value is written into that property of the feature before each re-evaluation.
    property: bpy.props.StringProperty()

    def value(self):
        """The value as procex takes it, clamped to the declared range."""
        if self.kind in ("FLOAT", "INT"):
            v = self.float_value if self.kind == "FLOAT" else self.int_value
            lo, hi = self.range()
            v = v if lo is None else max(v, lo)
            v = v if hi is None else min(v, hi)
            return float(v) if self.kind == "FLOAT" else int(v)
        if self.kind == "BOOL":
            return bool(self.bool_value)
        if self.kind == "ENUM":
            return self.enum_value
        if self.kind == "JSON":
            return json.loads(self.text_value)
        return self.text_value

    def range(self):
        """(min, max) as declared, None where unbounded."""
        return tuple(json.loads(self.bounds)) if self.bounds else (None, None)

    def range_text(self):
        lo, hi = self.range()
        if lo is None and hi is None:
            return self.unit
        lo = "-inf" if lo is None else f"{lo:g}"
        hi = "inf" if hi is None else f"{hi:g}"
        return f"{lo} .. {hi} {self.unit}".strip()


class ProcexSettings(bpy.types.PropertyGroup):
    recipe: bpy.props.StringProperty(subtype="FILE_PATH", description="The .pxg recipe this object is made from")
    feature: bpy.props.StringProperty(description="The GeoJSON feature it was evaluated for (batch), as JSON")
    params: bpy.props.CollectionProperty(type=ProcexParameter)
    error: bpy.props.StringProperty(description="Why the last evaluation failed; empty when it did not")
    last_ms: bpy.props.FloatProperty(description="Milliseconds the last evaluation and re-mesh took")


def _kind(p):
    if p.type == "float":
        return "FLOAT"
    if p.type == "int":
        return "INT"
    if p.type == "bool":
        return "BOOL"
    if p.type == "enum":
        return "ENUM"
    if p.type == "string":
        return "STRING"
    return "JSON"


def load(obj, recipe_path, feature=None, saved=None):
    """Points obj at a recipe and copies the recipe's exposed parameters (with
    their declared ranges and units) onto it, without evaluating; for a
    building (feature), with the values its properties give them. saved: the
    recipe as engine.as_saved loads it, when the caller has it already."""
    global _applying
    settings = obj.procex
    r = saved or engine.as_saved(recipe_path)
    _applying = True
    try:
        settings.recipe = str(r.path)
        settings.feature = json.dumps(feature) if feature is not None else ""
        settings.params.clear()
        for p in r.exposed if feature is None else r.exposed_for(feature):
            item = settings.params.add()
            item.name, item.kind, item.unit, item.doc = p.name, _kind(p), p.unit, p.doc
            item.property = p.property or ""
            item.bounds = json.dumps([p.min, p.max])
            if item.kind == "FLOAT":
                item.float_value = p.value
            elif item.kind == "INT":
                item.int_value = p.value
            elif item.kind == "BOOL":
                item.bool_value = p.value
            elif item.kind == "ENUM":
                item.choices = json.dumps(p.choices)
                item.enum_value = p.value
            elif item.kind == "STRING":
                item.text_value = p.value
            else:
                item.text_value = json.dumps(p.value)
    finally:
        _applying = False


def evaluate(obj):
    """Evaluates obj's recipe with obj's parameter values and replaces its mesh
    (and the objects placed on it) in place. Raises procex.Error."""
    start = time.perf_counter()
    settings = obj.procex
    r = engine.recipe(settings.recipe)
    feature = json.loads(settings.feature) if settings.feature else None
    for p in settings.params:
        r.set(p.name, p.value())
        if p.property:
            feature["properties"][p.property] = p.value()
    parts = r.evaluate(footprint=feature)
    mesh_data.fill(obj.data, parts)
    mesh_data.place(obj, parts)
    settings.error = ""
    settings.last_ms = (time.perf_counter() - start) * 1000.0
    return parts


classes = (ProcexParameter, ProcexSettings)


def register():
    for c in classes:
        bpy.utils.register_class(c)
    bpy.types.Object.procex = bpy.props.PointerProperty(type=ProcexSettings)


def unregister():
    del bpy.types.Object.procex
    for c in reversed(classes):
        bpy.utils.unregister_class(c)
    engine.forget()
