"""Blender re-mesh time of the procex add-on (BENCHMARKS.md, "Python and
Blender"): the house recipe imported, its pitch changed back and forth; each
change re-evaluates through the recipe's cache and replaces the mesh in place.
Reports the median of the add-on's own timing (evaluate + fill the Blender
mesh), of that procex's evaluation alone, and the whole property change
(Blender's update dispatch included; headless, so no viewport redraw).

    BLENDER_USER_SCRIPTS=$(mktemp -d) blender -b --factory-startup --python bench/blender_remesh_bench.py -- \\
        build/blender/procex_blender.zip samples/house.pxg [CHANGES]
"""
import os
import statistics
import sys
import time

import bpy

addon, recipe = sys.argv[sys.argv.index("--") + 1:][:2]
changes = int(sys.argv[sys.argv.index("--") + 3]) if len(sys.argv) > sys.argv.index("--") + 3 else 100
bpy.ops.preferences.addon_install(filepath=os.path.abspath(addon), overwrite=True)
bpy.ops.preferences.addon_enable(module="procex_blender")
from procex_blender import engine  # noqa: E402

bpy.ops.import_scene.procex_recipe(filepath=os.path.abspath(recipe))
obj = bpy.context.active_object
pitch = obj.procex.params["pitch"]
base = pitch.float_value
remesh, setting, evaluate = [], [], []
r = engine.recipe(obj.procex.recipe)
# Every value new, so every change recomputes the branch it reaches (no cache hit on the sweep).
for i in range(changes):
    start = time.perf_counter()
    pitch.float_value = base + 10.0 * (i + 1) / changes  # Blender calls the update callback before returning
    setting.append((time.perf_counter() - start) * 1000)
    remesh.append(obj.procex.last_ms)
for i in range(changes):
    r.set("pitch", base - 10.0 * (i + 1) / changes)
    start = time.perf_counter()
    r.evaluate()
    evaluate.append((time.perf_counter() - start) * 1000)
print(f"procex add-on: {changes} pitch changes on {os.path.basename(recipe)}: re-mesh median "
      f"{statistics.median(remesh):.2f} ms (max {max(remesh):.2f}), of which procex evaluation "
      f"{statistics.median(evaluate):.2f} ms; the whole property change as the sidebar makes it "
      f"{statistics.median(setting):.2f} ms (max {max(setting):.2f})")
