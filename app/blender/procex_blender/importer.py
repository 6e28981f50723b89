"""What the add-on's File > Import operators share: the file browser, undo, and
a procex error (or a file that cannot be read) reported to the user with its
diagnostics instead of a Python traceback."""
import bpy
from bpy_extras.io_utils import ImportHelper

from . import engine


class ProcexImporter(ImportHelper):
    bl_options = {"REGISTER", "UNDO"}

    def execute(self, context):
        try:
            return self.run(context)
        except (engine.procex.Error, OSError, ValueError) as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}

    def run(self, context):
        """The import itself; returns the operator's result set."""
        raise NotImplementedError
