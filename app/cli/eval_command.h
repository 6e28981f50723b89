// `procex eval RECIPE -o out.(obj|ply|glb|gpkg) [--set name=value ...]
// [--footprints FILE.geojson --feature ID_OR_INDEX]`: evaluates a recipe's mesh
// outputs and writes them to one file (atomically). With --footprints, one
// feature is bound exactly as `procex batch` binds each one (feature_binding.h);
// its properties are applied after --set, as in batch.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/cli/mesh_run_options.h"

namespace procex {

struct EvalCommandOptions : MeshRunOptions {
  std::filesystem::path recipe;
  std::filesystem::path output;       // .obj, .ply, .glb or .gpkg
  std::vector<std::string> settings;  // name=value: exposed parameters or graph inputs
  std::filesystem::path footprints;   // GeoJSON FeatureCollection; empty: no feature bound
  std::string feature;                // the feature's id, or its index in the file
  std::string preset;                 // a preset of the recipe, applied before the settings
};

// 0: written; 1: a node failed (diagnostics on err, nothing written);
// 2: the recipe cannot be loaded, a setting is wrong, or the output cannot be written.
int run_eval(const EvalCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
