"""procex for Blender: procedural buildings from procex recipes (.pxg).

File > Import > procex recipe (.pxg) evaluates a recipe into a mesh object whose
exposed parameters appear in the sidebar (View3D > Sidebar > procex); changing
one re-evaluates the recipe (only the nodes the change reaches) and replaces the
mesh in place. File > Import > procex batch evaluates a recipe once per
footprint of any file procex batch reads (GeoJSON, Shapefile, GeoPackage,
FlatGeobuf, OSM): one object per building, named by its id, the feature's
attributes as custom properties, placed meshes (windows, chimneys) as linked
duplicates, one material per face tag (a Material node's look: a Principled BSDF,
its texture scaled to metres per tile), procex's texture coordinates (metres) as the
UV map and its flat normals.
"""

bl_info = {
    "name": "procex",
    "author": "procex",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import > procex recipe / procex batch; View3D > Sidebar > procex",
    "description": "Procedural extrusions (weighted straight skeleton with profiles) from procex recipes",
    "category": "Import-Export",
}

import bpy  # noqa: E402

from . import batch_import, panel, parameters, recipe_import  # noqa: E402

_importers = (recipe_import, batch_import)  # each an OPERATOR with its File > Import entry (menu)


def register():
    parameters.register()
    for m in _importers:
        bpy.utils.register_class(m.OPERATOR)
        bpy.types.TOPBAR_MT_file_import.append(m.menu)
    panel.register()


def unregister():
    panel.unregister()
    for m in reversed(_importers):
        bpy.types.TOPBAR_MT_file_import.remove(m.menu)
        bpy.utils.unregister_class(m.OPERATOR)
    parameters.unregister()
