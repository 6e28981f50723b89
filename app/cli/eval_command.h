// `procex eval RECIPE -o out.(obj|ply|glb|gpkg) [--set name=value ...]
// [--footprints FILE.geojson --feature ID_OR_INDEX]`: evaluates a recipe's mesh
// outputs and writes them to one file (atomically). With --footprints, one
// feature is bound exactly as `procex batch` binds each one (feature_binding.h);
// its properties are applied after --set, as in batch.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "nodes/support/mesh_export.h"
#include "app/cli/budget_settings.h"

namespace procex {

struct EvalCommandOptions {
  std::filesystem::path recipe;
  std::filesystem::path output;       // .obj, .ply, .glb or .gpkg
  std::vector<std::string> settings;  // name=value: exposed parameters or graph inputs
  std::filesystem::path footprints;   // GeoJSON FeatureCollection; empty: no feature bound
  std::string feature;                // the feature's id, or its index in the file
  std::vector<std::filesystem::path> allowed_paths;  // --allow-path: folders besides the recipe's its files may lie in
  std::string preset;                 // a preset of the recipe, applied before the settings
  ExportOptions export_options;       // --up, --crs (the footprints' CRS, core/io/footprint_read.h)
  std::string target_crs;             // --target-crs
  BudgetSettings budget;              // set on every Extrude node
  std::string layer;                  // --layer (core/io/footprint_read.h)
  std::optional<int> lod = std::nullopt;  // --lod: the level of detail (EvalOptions::lod)
  std::filesystem::path streets = {};     // --streets: street lines (FootprintReadOptions::streets)
  std::string streets_layer = {};         // --streets-layer
};

// 0: written; 1: a node failed (diagnostics on err, nothing written);
// 2: the recipe cannot be loaded, a setting is wrong, or the output cannot be written.
int run_eval(const EvalCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
