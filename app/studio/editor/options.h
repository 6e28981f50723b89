// options.h -- procex-studio's command line.
//
//   procex-studio [RECIPE.pxg | FILE.glb] [--screenshot OUT.png [--screenshot-info OUT.json]]
//                 [--size WxH] [--timeout SECONDS] [--autosave SECONDS]
//                 [--report-frames FILE] [--bench-edits N] [--ui-map FILE] [--select NODE]
//                 [--view YAW,PITCH] [--full-redraw] [--footprints FILE]
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace procex::studio {

struct Options {
  std::filesystem::path recipe;          // empty: start with an untitled recipe
  std::filesystem::path screenshot;      // render once evaluated, save this PNG, exit
  std::filesystem::path screenshot_info; // with --screenshot: JSON about what the image shows
  std::filesystem::path frame_report;    // write per-frame timings here on exit (benchmarks)
  std::filesystem::path footprints;      // a footprint file whose features the preview binds (as if dropped)
  std::filesystem::path ui_map;          // keep a JSON map of pins and widgets on screen here (input-driving tests)
  int width = 1280, height = 800;
  double timeout_s = 60.0;               // --screenshot: give up waiting for the evaluation
  int autosave_s = 30;                   // 0: no autosave
  unsigned select = 0;                   // a node id to select at start (screenshots of the inspector and editors)
  int bench_edits = 0;                   // benchmark: this many parameter edits, timed to the screen
  std::optional<std::array<float, 2>> view;  // the preview camera's yaw and pitch in degrees (e.g. from below the eaves)
  bool full_redraw = false;              // draw the whole window every frame (no partial redraw)
  bool help = false;
};

// Throws std::invalid_argument naming the bad argument.
Options parse_options(const std::vector<std::string>& args);
std::string usage();

}  // namespace procex::studio
