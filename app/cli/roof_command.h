// `procex roof`: extrudes every feature of a GeoJSON FeatureCollection with one
// roof angle (or per-edge angles from a feature property), validates each
// mesh, writes all of them into one mesh file (one group per feature id) and a
// JSON report with one entry per feature and a summary.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

#include "app/cli/budget_settings.h"

namespace procex {

struct RoofOptions {
  std::filesystem::path input;   // GeoJSON FeatureCollection of Polygon / MultiPolygon features
  double angle_deg = 45.0;       // every edge, unless angles_property gives per-edge angles
  std::string angles_property;   // feature property: one list of angles per ring, one per edge
  std::string crs, target_crs;   // --crs, --target-crs (core/io/footprint_read.h)
  std::string layer;             // --layer
  std::optional<double> max_height;
  std::filesystem::path output;  // .obj or .ply
  std::filesystem::path report;  // JSON
  int jobs = 0;                  // worker threads; 0 = one per hardware thread
  BudgetSettings budget;         // per footprint; unset limits keep SweepBudget's defaults
};

// Exit codes: 0 when no feature failed (refused inputs are not failures) and
// at least one was written, 1 when at least one feature failed or none was
// written, 2 when the input cannot be read or an
// output cannot be written. One line per refused or failed feature goes to
// `err`, the summary to `out`.
inline constexpr int kExitFeatureFailed = 1;
inline constexpr int kExitUnusableFile = 2;
int run_roof(const RoofOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
