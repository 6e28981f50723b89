"""File > Import > procex recipe (.pxg): one object holding the recipe's meshes."""
import os

import bpy

from . import parameters
from .importer import ProcexImporter


class PROCEX_OT_import_recipe(bpy.types.Operator, ProcexImporter):
    """Evaluate a procex recipe into a mesh object whose exposed parameters are in the sidebar"""

    bl_idname = "import_scene.procex_recipe"
    bl_label = "Import procex recipe"
    filename_ext = ".pxg"
    filter_glob: bpy.props.StringProperty(default="*.pxg", options={"HIDDEN"})

    def run(self, context):
        name = os.path.splitext(os.path.basename(self.filepath))[0]
        obj = bpy.data.objects.new(name, bpy.data.meshes.new(name))
        context.collection.objects.link(obj)
        try:
            parameters.load(obj, self.filepath)
            parameters.evaluate(obj)
        except BaseException:
            bpy.data.objects.remove(obj)  # no half-made object left behind
            raise
        for o in context.view_layer.objects:
            o.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        return {"FINISHED"}


def menu(self, context):
    self.layout.operator(PROCEX_OT_import_recipe.bl_idname, text="procex recipe (.pxg)")


OPERATOR = PROCEX_OT_import_recipe
