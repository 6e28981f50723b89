// What `procex eval` and `procex batch` share beyond the recipe: the folders
// its files may lie in, how footprints and street lines are read and bound,
// the sweep's budget, the level of detail, and how the meshes are written.
// One struct, registered on both commands by one function (main.cc), so the
// two cannot drift apart.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/budget_settings.h"
#include "nodes/support/mesh_export.h"

namespace procex {

struct MeshRunOptions {
  std::vector<std::filesystem::path> allowed_paths;  // --allow-path: folders besides the recipe's its files may lie in
  ExportOptions export_options;       // --up, --crs (the footprints' CRS, core/io/footprint_read.h)
  std::string target_crs;             // --target-crs
  BudgetSettings budget;              // set on every Extrude node
  std::string layer;                  // --layer (core/io/footprint_read.h)
  std::optional<int> lod = std::nullopt;  // --lod: the level of detail (EvalOptions::lod)
  std::filesystem::path streets = {};     // --streets: street lines (FootprintReadOptions::streets)
  std::string streets_layer = {};         // --streets-layer
};

}  // namespace procex
