// `procex merge PARTS... -o OUT.glb [--report OUT.json]`: joins the outputs of
// a sharded `procex batch` (its .glb files, and its .json reports if --report
// is given) into the file an unsharded run writes: buildings ordered by their
// feature's position in the GeoJSON file, placed meshes (instanced windows) kept
// instanced and written once.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <vector>

namespace procex {

struct MergeCommandOptions {
  std::vector<std::filesystem::path> parts;  // .glb shard outputs and .json shard reports
  std::filesystem::path output;              // .glb
  std::filesystem::path report;              // merged report; empty: none (then .json parts are refused)
};

// 0: written; 2: a part cannot be read or the output not written.
int run_merge(const MergeCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
