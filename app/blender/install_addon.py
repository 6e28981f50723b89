"""Installs and enables the procex add-on in the user's Blender, and saves the
preferences so it stays enabled (scripts/setup.sh sample runs this).

    blender -b --python app/blender/install_addon.py -- build/blender/procex_blender.zip
"""
import sys

import bpy

addon = sys.argv[sys.argv.index("--") + 1]
bpy.ops.preferences.addon_install(filepath=addon, overwrite=True)
bpy.ops.preferences.addon_enable(module="procex_blender")
bpy.ops.wm.save_userpref()
print("procex add-on installed and enabled from", addon)
