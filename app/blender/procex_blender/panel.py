"""View3D > Sidebar > procex: the active object's recipe parameters."""
import bpy


class PROCEX_PT_parameters(bpy.types.Panel):
    bl_label = "procex"
    bl_idname = "PROCEX_PT_parameters"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "procex"

    @classmethod
    def poll(cls, context):
        return context.object is not None and context.object.procex.recipe != ""

    def draw(self, context):
        settings = context.object.procex
        layout = self.layout
        layout.label(text=bpy.path.basename(settings.recipe), icon="NODETREE")
        for p in settings.params:
            field = {"FLOAT": "float_value", "INT": "int_value", "BOOL": "bool_value", "ENUM": "enum_value"}
            row = layout.row()
            row.prop(p, field.get(p.kind, "text_value"), text=p.name)
            row.label(text=p.range_text())
        if settings.error:
            for line in settings.error.splitlines():
                layout.label(text=line, icon="ERROR")
        else:
            layout.label(text=f"{settings.last_ms:.1f} ms")


def register():
    bpy.utils.register_class(PROCEX_PT_parameters)


def unregister():
    bpy.utils.unregister_class(PROCEX_PT_parameters)
