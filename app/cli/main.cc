// procex: the command line. CLI11 lives in this file only (it costs seconds
// per translation unit); each subcommand is a plain options struct and a run
// function in its own <name>_command.{h,cc}, bound here by one add_* function.
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "app/cli/merge_command.h"
#include "app/cli/mesh_run_options.h"
#include "app/cli/recipe_session.h"
#include "app/cli/nodes_command.h"
#include "app/cli/roof_command.h"
#include "app/cli/stats_command.h"
#include "app/cli/validate_command.h"

namespace procex {
namespace {

using Runner = std::function<int()>;

// CLI11's range checks compare, and every comparison with NaN is false: a
// number option must be finite before its range means anything.
const CLI::Validator kFinite(
    [](std::string& text) {
      double v = 0;
      if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v)) return std::string("not a finite number: ") + text;
      return std::string();
    },
    "FINITE");

// Every command that evaluates a recipe keeps its files inside the recipe's
// folder unless the user names more folders.
void add_allow_path(CLI::App* cmd, std::vector<std::filesystem::path>& folders) {
  cmd->add_option("--allow-path", folders,
                  "A folder outside the recipe's own whose files the recipe may read or write (repeatable; only for "
                  "recipes you trust)")
      ->check(CLI::ExistingDirectory);
}

// --crs, --target-crs and --layer for the commands that read footprints (core/io/footprint_read.h).
void add_footprint_options(CLI::App* cmd, std::string& crs, std::string& target_crs, std::string& layer) {
  cmd->add_option("--crs", crs,
                  "The footprints' coordinate reference system (EPSG:4326, EPSG:32632, a WKT or a PROJ string), "
                  "replacing the file's own (.prj, GeoPackage srs, GeoJSON \"crs\"). A projected CRS in metres is "
                  "built in as it is and a .gpkg, .json (CityJSON) or .glb output is georeferenced in it; longitude/latitude (or feet) is projected "
                  "to a transverse Mercator centred on the data, true to size there. A file declaring no CRS is taken "
                  "in metres, but refused if all its coordinates are longitude/latitude and every footprint would be "
                  "under 5 cm across: give --crs then. Without footprints (eval): the output's CRS");
  cmd->add_option("--target-crs", target_crs,
                  "The projected CRS in metres to build in (and georeference the output in) instead, e.g. the UTM "
                  "zone (EPSG:32632; CityJSON needs one with an EPSG code); needs the footprints' CRS");
  cmd->add_option("--layer", layer,
                  "The layer of the footprint file to read (a GeoPackage's table, an OSM file's layer); default: "
                  "the first (OSM: multipolygons). A name the file lacks is refused, listing its layers");
}

// --lod for the commands that evaluate a recipe into mesh files.
void add_lod_option(CLI::App* cmd, std::optional<int>& lod) {
  cmd->add_option_function<int>(
         "--lod", [&lod](int level) { lod = level; },
         "Level of detail: 0 the footprints, 1 blocks at the roof's mean height (volume over footprint area, so "
         "a block holds its building's volume), 2 the roof shapes without placed meshes, 3 everything (default; "
         "also the recipe's graph input `lod` if it has one)")
      ->check(CLI::Range(0, kFullDetail));
}

// --streets and --streets-layer for the commands that bind footprints to a recipe.
void add_streets_options(CLI::App* cmd, std::filesystem::path& streets, std::string& layer) {
  cmd->add_option("--streets", streets,
                  "A second file (any format --footprints reads) whose LineStrings are street centre lines, besides "
                  "those of the footprint file itself: a footprint edge within 20 m of one, facing it over at least "
                  "half its length, is in the recipe's input street_edges (Assign Profiles' label street)");
  cmd->add_option("--streets-layer", layer, "The layer of --streets to read; default: the first");
}

// The sweep budget's options, the same on roof, eval and batch.
void add_budget_options(CLI::App* cmd, BudgetSettings& budget) {
  const SweepBudget defaults;
  cmd->add_option_function<std::int64_t>(
         "--max-vertices", [&budget](std::int64_t n) { budget.max_vertices = n; },
         "Refuse a footprint whose sweep makes more vertices, or more corners, or more events at one height (0: no "
         "limit; default " +
             std::to_string(defaults.max_vertices) + ")")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{1'000'000'000'000}));
  cmd->add_option_function<std::int64_t>(
         "--max-events", [&budget](std::int64_t n) { budget.max_events = n; },
         "Refuse a footprint whose sweep queues more potential events (0: no limit; default " +
             std::to_string(defaults.max_events) + ")")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{1'000'000'000'000'000}));
  cmd->add_option_function<double>(
         "--max-seconds", [&budget](double s) { budget.max_seconds = s; },
         "Refuse a footprint whose sweep takes more CPU seconds (its thread's, so the machine's load does not "
         "change the result; 0: no limit; default " +
             std::to_string(static_cast<int>(defaults.max_seconds)) + ")")
      ->check(kFinite & CLI::Range(0.0, 1e6));
}

Runner add_roof(CLI::App& app) {
  auto options = std::make_shared<RoofOptions>();
  CLI::App* cmd = app.add_subcommand("roof", "Extrude every footprint of a GeoJSON file into a roof, validate it, "
                                             "write one mesh file and a JSON report");
  cmd->add_option("footprints", options->input, "Footprints: GeoJSON, Shapefile, GeoPackage, FlatGeobuf or OSM (.osm, .pbf: its buildings)")
      ->required();
  cmd->add_option("--angle", options->angle_deg, "Angle of every edge, degrees from the vertical (0 = wall)")
      ->check(kFinite & CLI::Range(-90.0, 90.0))
      ->capture_default_str();
  cmd->add_option("--angles-property", options->angles_property,
                  "Feature property with per-edge angles: one list per ring, one angle per edge");
  add_footprint_options(cmd, options->crs, options->target_crs, options->layer);
  cmd->add_option_function<double>(
         "--max-height", [options](double h) { options->max_height = h; }, "Cap the roofs with flat faces at this height")
      ->check(kFinite & CLI::PositiveNumber);
  cmd->add_option("-o,--output", options->output, "Mesh file for every feature (.obj or .ply)")->required();
  cmd->add_option("--report", options->report, "JSON report, one entry per feature")->required();
  cmd->add_option("-j,--jobs", options->jobs, "Worker threads (0 = one per hardware thread)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  add_budget_options(cmd, options->budget);
  return [cmd, options] { return *cmd ? run_roof(*options, std::cout, std::cerr) : -1; };
}

// --up for the commands that write OBJ or PLY: which file axis is up.
void add_up_option(CLI::App* cmd, ExportOptions& options) {
  cmd->add_option_function<std::string>(
         "--up", [&options](const std::string& axis) { options.up = axis == "z" ? UpAxis::Z : UpAxis::Y; },
         "Up axis of OBJ and PLY files: y (default; Blender, Maya, Houdini) or z (GIS tools: x east, y north, "
         "z up). Units are metres. A .glb is always +Y up with x east and -z north, as glTF 2.0 says, so a "
         "plan seen from above is not mirrored")
      ->check(CLI::IsMember({"y", "z"}));
}

// What eval and batch share (mesh_run_options.h).
void add_mesh_run_options(CLI::App* cmd, MeshRunOptions& options) {
  add_allow_path(cmd, options.allowed_paths);
  add_up_option(cmd, options.export_options);
  add_footprint_options(cmd, options.export_options.crs, options.target_crs, options.layer);
  add_budget_options(cmd, options.budget);
  add_lod_option(cmd, options.lod);
  add_streets_options(cmd, options.streets, options.streets_layer);
}

Runner add_eval(CLI::App& app) {
  auto options = std::make_shared<EvalCommandOptions>();
  CLI::App* cmd = app.add_subcommand("eval", "Evaluate a recipe (.pxg) and write its mesh outputs to one file");
  cmd->add_option("recipe", options->recipe, "Recipe file (.pxg)")->required();
  cmd->add_option("-o,--output", options->output,
                  "Mesh file: .obj (+ .mtl), .ply or .glb; or for GIS tools a GeoPackage (.gpkg) or CityJSON 2.0 "
                  "(.json, e.g. city.city.json), with --crs")
      ->required();
  cmd->add_option("--set", options->settings, "name=value for an exposed parameter or graph input (repeatable)");
  cmd->add_option("--preset", options->preset, "A named set of exposed values stored in the recipe, applied before --set");
  CLI::Option* footprints = cmd->add_option("--footprints", options->footprints,
                                            "Footprint file (GeoJSON, Shapefile, GeoPackage, FlatGeobuf, OSM): bind one feature as `procex batch` does");
  cmd->add_option("--feature", options->feature, "The feature's id, or its index in --footprints")->needs(footprints);
  footprints->needs("--feature");
  add_mesh_run_options(cmd, *options);
  cmd->get_option("--streets")->needs(footprints);
  return [cmd, options] { return *cmd ? run_eval(*options, std::cout, std::cerr) : -1; };
}

Runner add_validate(CLI::App& app) {
  auto options = std::make_shared<ValidateCommandOptions>();
  CLI::App* cmd = app.add_subcommand("validate", "Load and type-check a recipe; report problems without evaluating");
  cmd->add_option("recipe", options->recipe, "Recipe file (.pxg)")->required();
  add_allow_path(cmd, options->allowed_paths);
  return [cmd, options] { return *cmd ? run_validate(*options, std::cout, std::cerr) : -1; };
}

Runner add_stats(CLI::App& app) {
  auto options = std::make_shared<StatsCommandOptions>();
  CLI::App* cmd = app.add_subcommand("stats", "Evaluate a recipe; print per-node time, cache hits and memory");
  cmd->add_option("recipe", options->recipe, "Recipe file (.pxg)")->required();
  cmd->add_option("--set", options->settings, "name=value for an exposed parameter or graph input (repeatable)");
  add_allow_path(cmd, options->allowed_paths);
  return [cmd, options] { return *cmd ? run_stats(*options, std::cout, std::cerr) : -1; };
}

Runner add_nodes(CLI::App& app) {
  auto options = std::make_shared<NodesCommandOptions>();
  CLI::App* cmd = app.add_subcommand("nodes", "List the node types (documentation from their declarations)");
  cmd->add_flag("--markdown", options->markdown, "Full documentation as Markdown");
  return [cmd, options] { return *cmd ? run_nodes(*options, std::cout) : -1; };
}

Runner add_batch(CLI::App& app) {
  auto options = std::make_shared<BatchCommandOptions>();
  CLI::App* cmd = app.add_subcommand("batch", "Evaluate a recipe once per GeoJSON feature (bound to the input "
                                              "'footprint'; properties set exposed parameters of the same name)");
  cmd->add_option("recipe", options->recipe, "Recipe file (.pxg) with a graph input 'footprint'")->required();
  cmd->add_option("--footprints", options->footprints,
                  "Footprint file: GeoJSON, Shapefile, GeoPackage, FlatGeobuf or OSM (.osm, .pbf: its buildings)")
      ->required();
  cmd->add_option("-o,--output", options->output, "One mesh file (.obj, .ply, .glb), GeoPackage (.gpkg, "
                                                  "each building a feature) or CityJSON (.json), or a folder (ending in /) for one file "
                                                  "per building")->required();
  cmd->add_option("--format", options->format, "Per-building file format")
      ->check(CLI::IsMember({"obj", "ply", "glb", "gpkg", "json"}))
      ->capture_default_str();
  cmd->add_option("--report", options->report, "JSON report: one entry per building, failures with reasons");
  cmd->add_option("-j,--jobs", options->jobs, "Worker threads (0 = one per hardware thread)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option_function<std::string>(
      "--shard",
      [options](const std::string& s) {
        if (!parse_shard(s, options->shard, options->shards)) throw CLI::ValidationError("--shard", "expected i/N with 0 <= i < N");
      },
      "Take only features whose index is i modulo N (e.g. $SLURM_ARRAY_TASK_ID/$N)");
  cmd->add_option("--set", options->settings, "name=value applied to every building (repeatable)");
  cmd->add_option("--max-faces", options->max_faces, "Refuse a batch into one .obj, .ply, .gpkg or CityJSON file whose "
                                                     "buildings hold more faces (placed meshes' included) than this: "
                                                     "split it with --shard (a folder or a .glb streams out)")
      ->capture_default_str();
  cmd->add_option("--max-placed", options->max_placed, "Refuse a batch with more placed meshes than this")
      ->capture_default_str();
  cmd->add_flag("!--no-progress", options->progress, "No progress output");
  add_mesh_run_options(cmd, *options);
  return [cmd, options] { return *cmd ? run_batch(*options, std::cout, std::cerr) : -1; };
}

Runner add_merge(CLI::App& app) {
  auto options = std::make_shared<MergeCommandOptions>();
  CLI::App* cmd = app.add_subcommand("merge", "Join the .glb outputs (and .json reports) of sharded batch runs");
  cmd->add_option("parts", options->parts, "Shard outputs (.glb) and reports (.json)")->required();
  cmd->add_option("-o,--output", options->output, "Merged .glb")->required();
  cmd->add_option("--report", options->report, "Merged report (.json)");
  return [cmd, options] { return *cmd ? run_merge(*options, std::cout, std::cerr) : -1; };
}

}  // namespace
}  // namespace procex

int main(int argc, char** argv) {
  CLI::App app{"procex: procedural extrusions from the command line"};
  app.require_subcommand(1);
  std::vector<procex::Runner> commands = {procex::add_roof(app),     procex::add_eval(app),  procex::add_validate(app),
                                          procex::add_stats(app),    procex::add_nodes(app), procex::add_batch(app),
                                          procex::add_merge(app)};
  app.set_version_flag("--version", "procex 0.1");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints the problem (or the help, or the version); the process
    // keeps procex's codes: 0 for help and version, 2 for unusable options.
    return app.exit(e) == 0 ? 0 : procex::kExitUnusableInput;
  }
  for (const procex::Runner& run : commands)
    if (const int code = run(); code >= 0) return code;
  return 0;
}
