# Imports mesh files into Blender (headless) as an artist would, with the
# importers' default settings, and writes what Blender made of each as JSON:
# per mesh object its name, world bounds (Blender's Z up), UV maps, material
# names and looks (base colour, image), the highest point of the faces of
# each material, and its custom properties (what a .glb node's extras became).
#
#   blender -b --factory-startup --python tools/blender_import.py -- OUT.json FILE.glb FILE.obj ...
import json
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4.1 glTF importer still writes np.bool, an alias
# NumPy 1.24 (Debian 12's) removed: without it every import that has
# normals stops with AttributeError. The alias meant the builtin.
if not hasattr(numpy, 'bool'):
    numpy.bool = bool


def clear_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def look(material):
    """A material's base colour (where no texture feeds it) and the file name
    of the image texture it shows (None if none)."""
    colour, image = None, None
    if material.use_nodes:
        for node in material.node_tree.nodes:
            if node.type == 'TEX_IMAGE' and node.image:
                image = bpy.path.basename(node.image.filepath)
            if node.type == 'BSDF_PRINCIPLED' and not node.inputs['Base Color'].is_linked:
                colour = list(node.inputs['Base Color'].default_value)[:3]
    else:
        colour = list(material.diffuse_color)[:3]
    return {'colour': colour, 'image': image}


def plain(value):
    """A custom property as JSON: groups and arrays as dicts and lists."""
    if hasattr(value, 'to_dict'):
        return value.to_dict()
    if hasattr(value, 'to_list'):
        return value.to_list()
    return value


def describe():
    objects = []
    for o in bpy.context.scene.objects:
        if o.type != 'MESH':
            continue
        corners = [o.matrix_world @ Vector(c) for c in o.bound_box]
        mesh = o.data
        top_by_material = {}
        for poly in mesh.polygons:
            name = o.material_slots[poly.material_index].name if o.material_slots else ''
            top = max((o.matrix_world @ mesh.vertices[v].co).z for v in poly.vertices)
            top_by_material[name] = max(top, top_by_material.get(name, -1e300))
        objects.append({
            'name': o.name,
            'parent': o.parent.name if o.parent else None,
            'min': [min(c[k] for c in corners) for k in range(3)],
            'max': [max(c[k] for c in corners) for k in range(3)],
            'uv_maps': [uv.name for uv in mesh.uv_layers],
            'materials': [s.material.name for s in o.material_slots if s.material],
            'looks': {s.material.name: look(s.material) for s in o.material_slots if s.material},
            'top_by_material': top_by_material,
            'faces': len(mesh.polygons),
            'properties': {k: plain(o[k]) for k in o.keys()},
        })
    return objects


def main():
    args = sys.argv[sys.argv.index('--') + 1:]
    out, files = args[0], args[1:]
    report = {}
    for f in files:
        clear_scene()
        if f.lower().endswith('.glb'):
            bpy.ops.import_scene.gltf(filepath=f)
        elif f.lower().endswith('.obj'):
            bpy.ops.wm.obj_import(filepath=f)
        else:
            raise SystemExit(f'{f}: not .glb or .obj')
        report[f] = describe()
    with open(out, 'w') as o:
        json.dump(report, o, indent=1)


main()
