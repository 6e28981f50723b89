"""File > Import > procex batch: a recipe over every footprint of a footprint
file, as procex batch runs it (in parallel, outside Python's lock, a window of
buildings at a time)."""
import json
import os

import bpy

from . import engine, mesh_data, parameters
from .importer import ProcexImporter


def _property(value):
    """A GeoJSON property value as a Blender custom property (nested values as JSON text)."""
    if isinstance(value, (bool, int, float, str)):
        return value
    return json.dumps(value)


def import_batch(context, footprints, recipe_path, jobs=0):
    """One object per building (named by its id) in a new collection named after
    the file; returns (collection, the buildings that are not ok, how many there
    were). The footprints are any file procex batch reads (GeoJSON, Shapefile,
    GeoPackage, FlatGeobuf, OSM): each building keeps the feature as procex
    evaluated it (its outline in the batch's frame, its party and street edges),
    so a parameter change re-evaluates the same building. The buildings come
    from procex.batch_iter one at a time and are dropped once in Blender, so
    procex holds a few windows of them, never the whole city's meshes."""
    wm = context.window_manager
    recipe = engine.as_saved(recipe_path)
    shared = {}  # placed meshes: one Blender mesh each, shared by every building
    not_ok = []
    wm.progress_begin(0, 1)
    try:
        # The with block stops procex's workers if Blender fails (or Ctrl+C) part way.
        with engine.procex.batch_iter(recipe, footprints, jobs=jobs) as buildings:
            total = len(buildings)
            # Made once the footprints are read: a file procex refuses leaves no empty collection.
            collection = bpy.data.collections.new(os.path.splitext(os.path.basename(footprints))[0])
            context.scene.collection.children.link(collection)
            for done, b in enumerate(buildings, 1):
                wm.progress_update(done / total)
                if b.status != "ok":
                    not_ok.append(b)
                    continue
                obj = bpy.data.objects.new(b.id, mesh_data.fill(bpy.data.meshes.new(b.id), b.meshes))
                collection.objects.link(obj)
                for key, value in b.feature["properties"].items():
                    if value is not None:
                        obj[key] = _property(value)
                parameters.load(obj, recipe_path, b.feature, recipe)
                mesh_data.place(obj, b.meshes, shared)
    finally:
        wm.progress_end()
    return collection, not_ok, total


class PROCEX_OT_import_batch(bpy.types.Operator, ProcexImporter):
    """Evaluate a procex recipe for every footprint of a footprint file: one object per building"""

    bl_idname = "import_scene.procex_batch"
    bl_label = "Import procex batch"
    filename_ext = ".geojson"
    filter_glob: bpy.props.StringProperty(default="*.geojson;*.json;*.shp;*.gpkg;*.fgb;*.osm;*.pbf", options={"HIDDEN"})
    recipe: bpy.props.StringProperty(name="Recipe", subtype="FILE_PATH",
                                     description="The .pxg recipe evaluated for every footprint")
    jobs: bpy.props.IntProperty(name="Threads", default=0, min=0, description="0: one per core")

    def run(self, context):
        _, failed, total = import_batch(context, self.filepath, bpy.path.abspath(self.recipe), self.jobs)
        for b in failed:
            self.report({"WARNING"}, f"{b.id}: {b.status}: {b.reason}")
        self.report({"INFO"}, f"{total - len(failed)} of {total} buildings")
        return {"FINISHED"}


def menu(self, context):
    self.layout.operator(PROCEX_OT_import_batch.bl_idname, text="procex batch (footprints + .pxg)")


OPERATOR = PROCEX_OT_import_batch
