// procex: the command line. CLI11 lives in this file only (it costs seconds
// per translation unit); each subcommand is a plain options struct and a run
// function in its own <name>_command.{h,cc}, bound here by one add_* function.
#include <functional>
#include <iostream>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli/roof_command.h"

namespace procex {
namespace {

using Runner = std::function<int()>;

Runner add_roof(CLI::App& app) {
  auto options = std::make_shared<RoofOptions>();
  CLI::App* cmd = app.add_subcommand("roof", "Extrude every footprint of a GeoJSON file into a roof, validate it, "
                                             "write one mesh file and a JSON report");
  cmd->add_option("footprints", options->input, "GeoJSON FeatureCollection of Polygon/MultiPolygon features")
      ->required();
  cmd->add_option("--angle", options->angle_deg, "Angle of every edge, degrees from the vertical (0 = wall)")
      ->check(CLI::Range(-90.0, 90.0))
      ->capture_default_str();
  cmd->add_option("--angles-property", options->angles_property,
                  "Feature property with per-edge angles: one list per ring, one angle per edge");
  cmd->add_option_function<double>(
         "--max-height", [options](double h) { options->max_height = h; }, "Cap the roofs with flat faces at this height")
      ->check(CLI::PositiveNumber);
  cmd->add_option("-o,--output", options->output, "Mesh file for every feature (.obj or .ply)")->required();
  cmd->add_option("--report", options->report, "JSON report, one entry per feature")->required();
  cmd->add_option("-j,--jobs", options->jobs, "Worker threads (0 = one per hardware thread)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  return [cmd, options] { return *cmd ? run_roof(*options, std::cout, std::cerr) : -1; };
}

}  // namespace
}  // namespace procex

int main(int argc, char** argv) {
  CLI::App app{"procex: procedural extrusions from the command line"};
  app.require_subcommand(1);
  std::vector<procex::Runner> commands = {procex::add_roof(app)};
  CLI11_PARSE(app, argc, argv);
  for (const procex::Runner& run : commands)
    if (const int code = run(); code >= 0) return code;
  return 0;
}
