"""The procex add-on in Blender, headless (tests/blender/CMakeLists.txt runs it):
installs and enables it from the zip the build makes, imports the house
recipe, changes exposed parameters and checks the mesh changed in place as the
procex module says it should (vertex count, bounds and volume through bmesh),
then imports the 18 sample-block buildings as a batch. Every mesh carries
procex's UV map (metres: a wall's u spans its edge, v is its height) and its
flat normals, checked against Blender's own geometry.

    blender -b --factory-startup --python-exit-code 1 --python addon_test.py -- ADDON.zip SAMPLES_DIR
"""
import collections
import json
import os
import shutil
import subprocess
import sys
import tempfile

import bmesh
import bpy

addon, samples = sys.argv[sys.argv.index("--") + 1:][:2]


def check(condition, message):
    if not condition:
        raise AssertionError(message)


def close(a, b, tolerance, what):
    check(abs(a - b) <= tolerance, f"{what}: {a} != {b} (tolerance {tolerance})")


def measure(obj):
    """Vertex and face counts, bounds and volume of an object's mesh, through bmesh."""
    bm = bmesh.new()
    bm.from_mesh(obj.data)
    co = [v.co for v in bm.verts]
    result = {
        "vertices": len(bm.verts),
        "faces": len(bm.faces),
        "min": [min(c[i] for c in co) for i in range(3)],
        "max": [max(c[i] for c in co) for i in range(3)],
        "volume": bm.calc_volume(signed=True),
    }
    bm.free()
    return result


def module_summary(parts):
    """The same numbers from the procex module's arrays (the reference)."""
    import numpy as np

    v = np.concatenate([p.vertices for p in parts])
    volume = 0.0
    for p in parts:
        for f in range(p.n_faces):
            pts = p.vertices[p.face_indices[p.face_offsets[f]:p.face_offsets[f + 1]]]
            volume += sum(np.dot(pts[0], np.cross(pts[k], pts[k + 1])) for k in range(1, len(pts) - 1)) / 6.0
    return {"vertices": len(v), "faces": sum(p.n_faces for p in parts), "min": v.min(axis=0), "max": v.max(axis=0),
            "volume": volume}


def same(got, want, what):
    """Blender stores float32 coordinates: compare within what float32 keeps."""
    check(got["vertices"] == want["vertices"], f"{what}: {got['vertices']} vertices, want {want['vertices']}")
    check(got["faces"] == want["faces"], f"{what}: {got['faces']} faces, want {want['faces']}")
    for end in ("min", "max"):
        for i in range(3):
            close(got[end][i], want[end][i], 1e-4 * max(1.0, abs(want[end][i])), f"{what} {end}[{i}]")
    close(got["volume"], want["volume"], 1e-5 * abs(want["volume"]), f"{what} volume")


def check_surface(obj, what):
    """One UV map, "UVMap", laying each face flat in metres (distances between
    corners kept); on walls v is the height and u spans the wall's bottom edge;
    each corner's normal is its face's (flat shading), as Blender computes it
    from the vertices."""
    me = obj.data
    check([uv.name for uv in me.uv_layers] == ["UVMap"], f"{what}: UV maps {[uv.name for uv in me.uv_layers]}")
    me.calc_normals_split()  # before taking the UV layer's data: it reallocates the corners' layers
    uv = me.uv_layers["UVMap"].data
    walls = 0
    for poly in me.polygons:
        loops = list(poly.loop_indices)
        co = [me.vertices[me.loops[k].vertex_index].co for k in loops]
        tex = [uv[k].uv for k in loops]
        for a, b in zip(range(len(loops)), list(range(1, len(loops))) + [0]):
            close((tex[b] - tex[a]).length, (co[b] - co[a]).length, 1e-3, f"{what} face {poly.index}: UV edge length")
        # Blender's own normal comes from float32 corners, so it is known only to
        # about the float32 spacing of the coordinates over the face's width: a
        # roof sliver 1 mm wide at 600 m from the origin (the sample block's
        # party walls make one) has no better direction than a few degrees.
        longest = max((co[b] - co[a]).length for a, b in zip(range(len(co)), list(range(1, len(co))) + [0]))
        width = 2.0 * poly.area / longest
        span = max(abs(x) for c in co for x in c)
        tolerance = max(1e-3, 4.0 * 2.0**-23 * span / width) if width > 0.0 else 2.0
        for k in loops:
            close((me.loops[k].normal - poly.normal).length, 0.0, tolerance, f"{what} face {poly.index}: corner normal")
        material = me.materials[poly.material_index].name if me.materials else ""
        if material == "procex wall":
            walls += 1
            for t, c in zip(tex, co):
                close(t.y, c.z, 1e-3, f"{what} wall {poly.index}: v is the height")
            low = min(c.z for c in co)
            bottom = [c for c in co if abs(c.z - low) < 1e-4]
            edge = max((p.xy - q.xy).length for p in bottom for q in bottom)
            close(max(t.x for t in tex) - min(t.x for t in tex), edge, 1e-3, f"{what} wall {poly.index}: u span")
    return walls


# ---- install and enable, as a user would from Preferences > Add-ons > Install
bpy.ops.preferences.addon_install(filepath=addon, overwrite=True)
bpy.ops.preferences.addon_enable(module="procex_blender")
check("procex_blender" in bpy.context.preferences.addons, "the add-on is not enabled")
from procex_blender import engine  # noqa: E402

procex = engine.procex
check(hasattr(bpy.types, "PROCEX_PT_parameters"), "the sidebar panel is not registered")
from procex_blender import batch_import, recipe_import  # noqa: E402

file_import = bpy.types.TOPBAR_MT_file_import._dyn_ui_initialize()  # the functions drawing File > Import's entries
check(recipe_import.menu in file_import and batch_import.menu in file_import,
      "File > Import has no procex recipe or procex batch entry")

# ---- File > Import > procex recipe
house = os.path.join(samples, "house.pxg")
check(bpy.ops.import_scene.procex_recipe(filepath=house) == {"FINISHED"}, "importing house.pxg failed")
obj = bpy.context.active_object
check(obj is not None and obj.name == "house", "the imported object is not active or not named house")
stored = json.load(open(os.path.join(samples, "expected", "house.json")))
got = measure(obj)
check(got["faces"] == stored["faces"], f"house: {got['faces']} faces, stored {stored['faces']}")
close(got["volume"], stored["volume"], 1e-5 * stored["volume"], "house volume")
for end in ("min", "max"):
    for i in range(3):
        close(got[end][i], stored["bounds"][end][i], 1e-4, f"house {end}[{i}]")
materials = {m.name for m in obj.data.materials}
check(materials == {"procex " + t for t in stored["faces_per_tag"]}, f"materials per tag: {materials}")
check(check_surface(obj, "house") == stored["faces_per_tag"]["wall"], "house: not every wall checked")
per_material = collections.Counter(obj.data.materials[p.material_index].name for p in obj.data.polygons)
check(per_material == {"procex " + t: n for t, n in stored["faces_per_tag"].items()}, f"faces per material: {per_material}")

# the panel's parameters are the recipe's exposed ones, with ranges and units
params = obj.procex.params
check([p.name for p in params] == ["shape", "pitch"], f"parameters: {[p.name for p in params]}")
pitch = params["pitch"]
lowest, highest = pitch.range()
declared_all = procex.Recipe.load(house).exposed
declared = {p.name: p for p in declared_all}["pitch"]
check(pitch.kind == "FLOAT" and pitch.unit == "deg" and (lowest, highest) == (declared.min, declared.max),
      f"pitch range or unit: {pitch.range_text()}")
check(lowest < pitch.float_value < highest, "pitch outside its range")
check("deg" in pitch.range_text(), pitch.range_text())

# ---- change an exposed parameter: the mesh is replaced in place
mesh_name = obj.data.name
before = got
pitch.float_value = pitch.float_value - 10  # steeper (degrees from the vertical); the update callback re-evaluates
check(obj.procex.error == "", obj.procex.error)
after = measure(obj)
check(bpy.data.objects["house"] == obj and obj.data.name == mesh_name, "the mesh was not replaced in place")
check(after["vertices"] == before["vertices"], "a steeper roof keeps the vertex count")
check(after["max"][2] > before["max"][2] + 0.5, f"the roof did not rise: {before['max'][2]} -> {after['max'][2]}")
check(after["volume"] > before["volume"], "the volume did not grow")
reference = procex.Recipe.load(house)
reference.set("pitch", pitch.float_value)
same(after, module_summary(reference.evaluate()), "house at the new pitch")
check_surface(obj, "house at the new pitch")  # replaced in place: still one UV map
# through the recipe's cache: only the branch the pitch reaches was computed again
outcomes = {path: outcome for path, _, outcome in engine.recipe(house).last_evaluation}
nodes = {p.name: p.node for p in declared_all}
check(outcomes[nodes["pitch"]] == "computed" and outcomes[nodes["shape"]] == "cache hit",
      f"the pitch change did not go through the cache: {outcomes}")
print(f"procex add-on: house re-mesh after a pitch change {obj.procex.last_ms:.1f} ms")

params["shape"].enum_value = "rectangle"
reference.set("shape", "rectangle")
same(measure(obj), module_summary(reference.evaluate()), "house as a rectangle")
check(measure(obj)["vertices"] != after["vertices"], "the shape change did not change the mesh")

# an out-of-range value is clamped to the declared range, as the panel shows it
pitch.float_value = highest + 100
check(obj.procex.error == "", obj.procex.error)
reference.set("pitch", highest)
same(measure(obj), module_summary(reference.evaluate()), "house at the largest pitch")

# ---- a recipe procex refuses: the operator reports procex's diagnostic and leaves no object behind
broken = os.path.join(tempfile.mkdtemp(), "broken.pxg")
with open(broken, "w") as f:
    f.write('{"procex": 1, "nodes": [')
objects = len(bpy.data.objects)
try:
    bpy.ops.import_scene.procex_recipe(filepath=broken)
    message = ""
except RuntimeError as e:  # an operator's ERROR report, as a headless Blender raises it
    message = str(e)
check("broken.pxg" in message, f"the error does not name the file: {message!r}")
check(len(bpy.data.objects) == objects, "a refused import left an object behind")

# ---- placed meshes are linked duplicates
grid = os.path.join(samples, "windows_grid.pxg")
check(bpy.ops.import_scene.procex_recipe(filepath=grid) == {"FINISHED"}, "importing windows_grid.pxg failed")
building = bpy.context.active_object
placed = [c for c in building.children if c.get("procex_placed")]
check(len(placed) == 28, f"{len(placed)} placed objects, want 28")
shared = {c.data.name for c in placed}
check(len(shared) == 2, f"placed meshes are not shared: {len(shared)} meshes")
check(sum(bpy.data.meshes[n].users for n in shared) == 28, "each placed mesh is used by its placements")
for c in placed[:1] + placed[-1:]:
    check_surface(c, c.name)
params = building.procex.params
params["spacing"].float_value = params["spacing"].float_value * 2  # wider spacing: fewer windows
again = [c for c in building.children if c.get("procex_placed")]
check(0 < len(again) < 28, f"{len(again)} placed objects after doubling the spacing")

# ---- a placed mesh's own materials: the sample door's colour and texture image, its own UVs
textured = tempfile.mkdtemp()
shutil.copytree(os.path.join(samples, "meshes"), os.path.join(textured, "meshes"))
with open(grid) as f:
    recipe = f.read().replace('"file": "meshes/window_frame.obj"', '"file": "meshes/door_textured.obj"', 1)
with open(os.path.join(textured, "doors.pxg"), "w") as f:
    f.write(recipe)
check(bpy.ops.import_scene.procex_recipe(filepath=os.path.join(textured, "doors.pxg")) == {"FINISHED"},
      "importing the textured doors failed")
doors = [c for c in bpy.context.active_object.children
         if c.get("procex_placed") and "procex door" in {m.name for m in c.data.materials}]
check(doors, "no door was placed")
door = doors[0].data
slots = {m.name: m for m in door.materials}
check(set(slots) == {"procex door", "procex door_frame"}, f"door materials: {set(slots)}")
frame = slots["procex door_frame"]
bsdf = next(n for n in frame.node_tree.nodes if n.type == "BSDF_PRINCIPLED")
check(tuple(round(c, 6) for c in bsdf.inputs["Base Color"].default_value[:3]) == (0.2, 0.25, 0.3),
      f"door frame colour: {tuple(bsdf.inputs['Base Color'].default_value)}")
face = slots["procex door"]
bsdf = next(n for n in face.node_tree.nodes if n.type == "BSDF_PRINCIPLED")
links = [l for l in face.node_tree.links if l.to_socket == bsdf.inputs["Base Color"]]
check(len(links) == 1 and links[0].from_node.type == "TEX_IMAGE", "the door's base colour is not its image")
image = links[0].from_node.image
check(os.path.samefile(bpy.path.abspath(image.filepath), os.path.join(textured, "meshes", "door_planks.png")),
      f"the door's image is {image.filepath}")
check(tuple(image.size) == (16, 32), f"the door's image did not load: size {tuple(image.size)}")
front = [p for p in door.polygons if door.materials[p.material_index] == face]
check(len(front) == 1, f"{len(front)} faces show the door's image")
uv = door.uv_layers["UVMap"].data
corners = {(round(uv[i].uv[0], 6), round(uv[i].uv[1], 6)) for i in front[0].loop_indices}
check(corners == {(0, 0), (1, 0), (1, 1), (0, 1)}, f"the door's face does not keep its own UVs: {corners}")
shutil.rmtree(textured)

# ---- Material nodes: each tag's Principled BSDF (colour, roughness, metalness) and its image seen
# through a Mapping node scaling the UVs (metres) by 1 / tile_size; a new tile size makes a new material
def looks(obj):
    """The object's materials by tag (Blender's .001 suffix of a second look taken off)."""
    return {m.name.split(".")[0][len("procex "):]: m for m in obj.data.materials}


def principled(m):
    return next(n for n in m.node_tree.nodes if n.type == "BSDF_PRINCIPLED")


def image_and_scale(m):
    """The image behind the base colour and the Mapping node's scale in front of it."""
    bsdf = principled(m)
    links = [l for l in m.node_tree.links if l.to_socket == bsdf.inputs["Base Color"]]
    check(len(links) == 1 and links[0].from_node.type == "TEX_IMAGE", f"{m.name}: the base colour is not an image")
    node = links[0].from_node
    into = [l for l in m.node_tree.links if l.to_socket == node.inputs["Vector"]]
    check(len(into) == 1 and into[0].from_node.type == "MAPPING", f"{m.name}: no Mapping node scales the UVs")
    uv = [l for l in m.node_tree.links if l.to_socket == into[0].from_node.inputs["Vector"]]
    check(len(uv) == 1 and uv[0].from_socket.name == "UV", f"{m.name}: the Mapping node does not read the UVs")
    return node.image, tuple(round(c, 6) for c in into[0].from_node.inputs["Scale"].default_value)


house_path = os.path.join(samples, "textured_house.pxg")
check(bpy.ops.import_scene.procex_recipe(filepath=house_path) == {"FINISHED"}, "importing the textured house failed")
textured_house = bpy.context.active_object
tagged = looks(textured_house)
check(set(tagged) == {"base", "wall", "gable", "roof", "soffit"}, f"textured house materials: {set(tagged)}")
for tag, roughness, tile, image_name in (("wall", 0.85, 0.8, "brick.png"), ("gable", 0.85, 0.8, "brick.png"),
                                         ("roof", 0.6, 1.2, "roof_tiles.png")):
    m = tagged[tag]
    close(principled(m).inputs["Roughness"].default_value, roughness, 1e-6, f"{tag} roughness")
    close(principled(m).inputs["Metallic"].default_value, 0.0, 1e-6, f"{tag} metallic")
    image, scale = image_and_scale(m)
    check(os.path.samefile(bpy.path.abspath(image.filepath), os.path.join(samples, "textures", image_name)),
          f"{tag}: the image is {image.filepath}")
    check(tuple(image.size) == (64, 64), f"{tag}: the image did not load: size {tuple(image.size)}")
    check(scale == (round(1 / tile, 6), round(1 / tile, 6), 1.0), f"{tag}: the UVs are scaled by {scale}")
check(image_and_scale(tagged["wall"])[0] == image_and_scale(tagged["gable"])[0], "the brick image is loaded twice")
soffit = principled(tagged["soffit"])
check(tuple(round(c, 6) for c in soffit.inputs["Base Color"].default_value[:3]) == (0.9, 0.9, 0.85),
      f"soffit colour: {tuple(soffit.inputs['Base Color'].default_value)}")
close(soffit.inputs["Roughness"].default_value, 0.5, 1e-6, "soffit roughness")
check(not [l for l in tagged["soffit"].node_tree.links if l.to_socket == soffit.inputs["Base Color"]],
      "the soffit has an image")
textured_house.procex.params["brick_size"].float_value = 0.5
_, scale = image_and_scale(looks(textured_house)["wall"])
check(scale == (2.0, 2.0, 1.0), f"after brick_size = 0.5 the wall's UVs are scaled by {scale}")

# ---- batch: one object per building of the sample block
block = os.path.join(samples, "footprints", "sample_block.geojson")
city = os.path.join(samples, "city.pxg")
check(bpy.ops.import_scene.procex_batch(filepath=block, recipe=city) == {"FINISHED"}, "batch import failed")
collection = bpy.data.collections["sample_block"]
stored = json.load(open(os.path.join(samples, "expected", "city.json")))
features = {f["id"]: f for f in json.load(open(block))["features"]}
buildings = [o for o in collection.objects if not o.get("procex_placed")]
check(sorted(o.name for o in buildings) == sorted(stored["buildings"]), "buildings are not named by their ids")
for o in buildings:
    want = stored["buildings"][o.name]
    got = measure(o)
    close(got["volume"], want["volume"], 1e-5 * want["volume"], f"{o.name} volume")
    for end in ("min", "max"):
        for i in range(3):
            close(got[end][i], want["bounds"][end][i], 1e-3, f"{o.name} {end}[{i}]")
    check(got["faces"] == sum(want["faces_per_tag"].values()), f"{o.name} faces")
    check({m.name for m in o.data.materials} == {"procex " + t for t in want["faces_per_tag"]}, f"{o.name} materials")
    for key, value in features[o.name]["properties"].items():
        if value is not None:
            check(o[key] == value, f"{o.name}: custom property {key} = {o.get(key)!r}, want {value!r}")
    check(o.procex.recipe == city and o.procex.feature, f"{o.name} does not remember its recipe and feature")
    check(check_surface(o, o.name) == want["faces_per_tag"].get("wall", 0), f"{o.name}: not every wall checked")
windows = [o for o in collection.objects if o.get("procex_placed") and o.data.name.startswith("window")]
check(len({o.parent.name for o in windows}) > 1, "windows are placed on fewer than two buildings")
check(len({o.data.name for o in windows}) == 1, f"the buildings' windows are {len({o.data.name for o in windows})} meshes, not one shared")
print(f"procex add-on: {len(buildings)} buildings imported, {len(windows)} windows sharing one mesh")

# ---- a building re-evaluated on its own (as after a parameter change) is the building of the batch:
# its feature keeps the party walls procex found among its neighbours
from procex_blender import parameters  # noqa: E402

terraced = [o for o in buildings if json.loads(o["party_edges"])]
check(len(terraced) >= 5, f"{len(terraced)} buildings of the block have party walls")
for o in terraced:
    before = measure(o)
    parameters.evaluate(o)
    check(o.procex.error == "", o.procex.error)
    same(measure(o), before, f"{o.name} re-evaluated alone")

# ---- a parameter the building's feature sets (city.pxg's `building`, from the file's property) shows the
# feature's value in the panel, and changing it changes the building as procex makes it with that value
o = next(o for o in terraced if o["building"] != "church")
kind = o.procex.params["building"]
check(kind.text_value == o["building"] and kind.property == "building",
      f"{o.name}: the panel shows building = {kind.text_value!r} (property {kind.property!r}), the feature {o['building']!r}")
before = measure(o)
kind.text_value = "church"
check(o.procex.error == "", o.procex.error)
church = json.loads(o.procex.feature)
church["properties"]["building"] = "church"
want = module_summary(procex.Recipe.load(city).evaluate(footprint=church))
same(measure(o), want, f"{o.name} as a church")
check(measure(o)["max"][2] != before["max"][2], f"{o.name}: building = church did not change the building")

# ---- a batch from a GeoPackage (GDAL's ogr2ogr writes it): the same buildings, the attributes as GDAL read them,
# and the recipe's own values where a feature has none (not the church just set on one building)
gpkg = os.path.join(tempfile.mkdtemp(), "block_gpkg.gpkg")
subprocess.run(["ogr2ogr", "-a_srs", "EPSG:32632", gpkg, block], check=True)  # metres, as the GeoJSON
check(bpy.ops.import_scene.procex_batch(filepath=gpkg, recipe=city) == {"FINISHED"}, "GeoPackage batch import failed")
from_gpkg = [o for o in bpy.data.collections["block_gpkg"].objects if not o.get("procex_placed")]
check(sorted(o.name.split(".")[0] for o in from_gpkg) == sorted(stored["buildings"]),
      f"GeoPackage buildings: {sorted(o.name for o in from_gpkg)}")
for o in from_gpkg:
    name = o.name.split(".")[0]  # Blender's .001: the GeoJSON batch's objects have the names already
    want = stored["buildings"][name]
    close(measure(o)["volume"], want["volume"], 1e-5 * want["volume"], f"{name} from the GeoPackage: volume")
    for key, value in features[name]["properties"].items():
        if value is not None:
            check(o[key] == value, f"{name} from the GeoPackage: custom property {key} = {o.get(key)!r}, want {value!r}")
# ---- a batch of more buildings than procex evaluates at a time, with a footprint it refuses: the add-on takes
# them from procex.batch_iter one at a time, so procex holds a window of buildings, never the city's meshes. The
# refused one is reported, the others are the buildings procex.batch makes, and no procex worker outlives it.
from procex_blender import batch_import  # noqa: E402

sys.path.insert(0, os.path.join(samples, os.pardir, "tests", "python"))
from worker_threads import workers_once_joined  # noqa: E402


def rectangle(i):
    x, y = 40.0 * (i % 10), 40.0 * (i // 10)
    return [[[x, y], [x + 12 + i % 5, y], [x + 12 + i % 5, y + 9], [x, y + 9], [x, y]]]


generated = os.path.join(tempfile.mkdtemp(), "generated_block.geojson")
refused = 57
with open(generated, "w") as f:
    json.dump({"type": "FeatureCollection", "features": [
        {"type": "Feature", "id": f"g{i}", "properties": {"building:levels": 1 + i % 4},
         "geometry": {"type": "Polygon", "coordinates":
                      [[[0, 0], [10, 10], [10, 0], [0, 10], [0, 0]]] if i == refused else rectangle(i)}}
        for i in range(120)]}, f)
made, not_ok, total = batch_import.import_batch(bpy.context, generated, city, jobs=2)
check(total == 120, f"{total} buildings")
check([(b.id, b.status) for b in not_ok] == [(f"g{refused}", "refused")],
      f"not ok: {[(b.id, b.status, b.reason) for b in not_ok]}")
left = workers_once_joined(0)
check(not left, f"{left} procex workers left after the import")
imported = {o.name: o for o in made.objects if not o.get("procex_placed")}
reference = {b.id: b for b in procex.batch(procex.Recipe.load(city), generated, jobs=1) if b.status == "ok"}
check(sorted(imported) == sorted(reference) and len(reference) == 119, f"imported {sorted(imported)}")
for name, b in reference.items():
    same(measure(imported[name]), module_summary(b.meshes), f"{name} of the generated batch")
print(f"procex add-on: {len(imported)} of {total} generated buildings imported one at a time")
print("procex add-on test: ok")
