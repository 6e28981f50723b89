"""procex for Blender: procedural buildings from procex recipes (.pxg).

File > Import > procex recipe (.pxg) evaluates a recipe into a mesh object whose
exposed parameters appear in the sidebar (View3D > Sidebar > procex); changing
one re-evaluates the recipe (only the nodes the change reaches) and replaces the
mesh in place. File > Import > procex batch (.geojson) evaluates a recipe once
per footprint: one object per building, named by its id, the feature's
attributes as custom properties, placed meshes (windows, chimneys) as linked
duplicates, one material per face tag.
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

from . import batch_import, panel, parameters, recipe_import  # noqa: E402

_modules = (parameters, recipe_import, batch_import, panel)


def register():
    for m in _modules:
        m.register()


def unregister():
    for m in reversed(_modules):
        m.unregister()
