// `procex batch RECIPE --footprints city.geojson -o OUT [--report REPORT.json]
// [--jobs N] [--shard i/N] [--set name=value ...]`: evaluates a recipe once per
// GeoJSON feature. Each feature is bound to the graph input `footprint`, its id
// to the input `building_id` (if the recipe has one), and each property to the
// exposed parameter or graph input of the same name (characters other than
// a-z, 0-9 and _ become _, so building:levels sets building_levels).
// Features are evaluated in parallel; one failing feature is reported and the
// batch goes on. OUT is one mesh file (.obj, .ply, .glb) or GeoPackage
// (.gpkg, in --crs or the footprints' "crs": app/cli/output_crs.h) holding
// every building, or a folder (ending in / or existing) with one <id>.<format> per
// building. Output bytes do not depend on --jobs; shard i of N takes the
// features whose index is i modulo N, and `procex merge` joins the shards into
// the bytes an unsharded run writes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "app/cli/mesh_run_options.h"
#include "core/io/gltf_write.h"

namespace procex {

struct BatchCommandOptions : MeshRunOptions {
  std::filesystem::path recipe;
  std::filesystem::path footprints;  // GeoJSON FeatureCollection
  std::filesystem::path output;      // mesh file, or folder for one file per building
  std::string format = "glb";        // per-building files: obj, ply, glb or gpkg
  std::filesystem::path report;      // JSON; empty: none
  int jobs = 0;                      // worker threads; 0 = one per hardware thread
  std::size_t shard = 0, shards = 1;
  std::vector<std::string> settings;  // name=value applied to every building
  // What a batch into one .obj, .ply, .gpkg or CityJSON file may hold in
  // memory (building faces plus placed meshes' faces; placed meshes): more
  // is refused, exit 2, nothing written. A folder or a .glb streams out.
  std::size_t max_faces = 20000000, max_placed = 2000000;
  bool progress = true;               // progress on err: a bar on a terminal, else lines every 10%
  std::uint64_t glb_max_bytes = kGlbMaxBytes;  // what one .glb may hold: glTF's 4 GiB, less only in tests
};

// Parses "i/N" (0 <= i < N); false if malformed.
bool parse_shard(const std::string& text, std::size_t& shard, std::size_t& shards);

// 0: every building evaluated; 1: some failed (reported, the rest written),
// or none was written (every one refused, or no features);
// 2: unusable recipe, footprints or output.
int run_batch(const BatchCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
