"""File > Import > procex recipe (.pxg): one object holding the recipe's meshes."""
import os

import bpy
from bpy_extras.io_utils import ImportHelper

from . import engine, parameters


class PROCEX_OT_import_recipe(bpy.types.Operator, ImportHelper):
    """Evaluate a procex recipe into a mesh object whose exposed parameters are in the sidebar"""

    bl_idname = "import_scene.procex_recipe"
    bl_label = "Import procex recipe"
    bl_options = {"REGISTER", "UNDO"}
    filename_ext = ".pxg"
    filter_glob: bpy.props.StringProperty(default="*.pxg", options={"HIDDEN"})

    def execute(self, context):
        name = os.path.splitext(os.path.basename(self.filepath))[0]
        obj = bpy.data.objects.new(name, bpy.data.meshes.new(name))
        context.collection.objects.link(obj)
        try:
            parameters.load(obj, self.filepath)
            parameters.evaluate(obj)
        except engine.procex.Error as e:
            bpy.data.objects.remove(obj)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        for o in context.view_layer.objects:
            o.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        return {"FINISHED"}


def menu(self, context):
    self.layout.operator(PROCEX_OT_import_recipe.bl_idname, text="procex recipe (.pxg)")


OPERATOR = PROCEX_OT_import_recipe
