"""What scripts/setup.sh sample does for Blender, in a user folder of its
own: app/blender/install_addon.py installs and enables the add-on and saves
the preferences; a second Blender, started as a user starts it (the saved
preferences, no --factory-startup), has procex enabled and imports the house.

    python3 install_test.py BLENDER ADDON.zip SAMPLES_DIR
"""
import os
import pathlib
import subprocess
import sys
import tempfile

blender, addon, samples = sys.argv[1:4]
install = pathlib.Path(__file__).resolve().parents[2] / "app" / "blender" / "install_addon.py"
with tempfile.TemporaryDirectory() as user:
    env = {**os.environ, "BLENDER_USER_SCRIPTS": os.path.join(user, "scripts"),
           "BLENDER_USER_CONFIG": os.path.join(user, "config"), "PYTHONDONTWRITEBYTECODE": "1"}
    subprocess.run([blender, "-b", "--python-exit-code", "1", "--python", str(install), "--", addon], env=env, check=True)
    check = f"""
import bpy
assert "procex_blender" in bpy.context.preferences.addons, "procex is not enabled after a restart"
assert bpy.ops.import_scene.procex_recipe(filepath={os.path.join(samples, "house.pxg")!r}) == {{"FINISHED"}}
assert [p.name for p in bpy.context.active_object.procex.params] == ["shape", "pitch"]
print("procex add-on enabled from the saved preferences")
"""
    out = subprocess.run([blender, "-b", "--python-exit-code", "1", "--python-expr", check], env=env, check=True,
                         capture_output=True, text=True).stdout
    assert "enabled from the saved preferences" in out, out
print("install_addon.py: ok")
