// pxg.h -- the .pxg recipe file: canonical JSON, atomic saves, checked loads.
//
//   Graph g = load_pxg("recipes/block.pxg");         // throws PxgError
//   save_pxg(g, "recipes/block.pxg");                // temp file + rename
//
// Layout (version 2; keys sorted, nodes by id, links by destination, so two
// saves of the same graph are byte-identical):
//   { "format": "procex-graph", "version": 2,
//     "metadata": {"author": "", "description": "", "name": "", "licence": "CC-BY-4.0", "thumbnail": "house.png"},
//     "inputs":  [{"name": "footprint", "type": "footprint", "doc": "", "default": ...}],
//     "outputs": [{"name": "mesh", "type": "mesh", "doc": ""}],
//     "nodes":   [{"id": 3, "type": "Offset", "version": 1, "params": {"distance": 1.5}},
//                 {"id": 4, "group": "facade", "params": {...exposed...}}],
//     "links":   [{"from": "3.result", "to": "4.footprint"}, {"from": "@footprint", "to": "3.footprint"},
//                 {"from": "4.mesh", "to": "@mesh"}],
//     "exposed": [{"name": "height", "node": 3, "param": "distance", "label": "Height", "unit": "m", "min": 0, "max": 40}],
//     "presets": [{"name": "tall", "values": {"height": 30}}],
//     "groups":  [{"name": "facade", "file": "lib/facade.pxg"}, {"name": "inline", "graph": {...}}],
//     "editor":  {"nodes": {"3": {"x": 0, "y": 0, "comment": "", "collapsed": false}}} }
// licence, thumbnail, an exposed parameter's label/unit/min/max and presets
// are optional (written only when set). Parameters equal to their default are still written: a file means the same
// thing after a node's defaults change.
//
// Untrusted input: every problem is a PxgError naming the file and a line and
// column (syntax) or a JSON pointer (content). Unknown node types suggest the
// closest registered name. Sizes, nesting and group depth are bounded, and
// group files must lie inside the top recipe's folder.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "base/atomic_write.h"  // write_file_atomically: save_pxg uses it, and so do editors
#include "base/json_depth.h"
#include "graph/graph.h"

namespace procex {

inline constexpr const char* kPxgFormat = "procex-graph";
inline constexpr int kPxgVersion = 2;

struct PxgLimits {
  std::size_t max_file_bytes = std::size_t{32} << 20;
  std::size_t max_depth = kMaxJsonDepth;  // JSON nesting
  std::size_t max_nodes = 100000;    // per graph
  std::size_t max_links = 400000;    // per graph
  std::size_t max_string = 1 << 16;  // bytes per JSON string
  std::size_t max_group_depth = 16;  // groups inside groups, library files included
};

struct PxgOptions {
  const NodeRegistry* registry = &NodeRegistry::global();
  PxgLimits limits;
  // Group library files must resolve inside this folder. Empty: the folder of
  // the top-level recipe.
  std::filesystem::path root;
  // ... or inside one of these (what `--allow-path` adds; base/confined_path.h).
  std::vector<std::filesystem::path> allowed_folders;
  // Non-fatal notes (migrated from an older version...) are appended here.
  std::vector<std::string>* warnings = nullptr;
};

class PxgError : public std::runtime_error {
 public:
  PxgError(std::string file, std::string where, std::string message);
  const std::string& file() const { return file_; }
  // "line 3, column 14" or a JSON pointer such as "/nodes/2/params/distance".
  const std::string& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_, where_, message_;
};

Graph load_pxg(const std::filesystem::path& file, const PxgOptions& options = {});
// `file` names the text in messages and anchors relative group files.
Graph parse_pxg(std::string_view text, const std::filesystem::path& file, const PxgOptions& options = {});

// The canonical text of the current version (ends with a newline).
std::string to_pxg(const Graph& g);
// Writes to_pxg(g) through a temporary file in the same folder and a rename
// (write_file_atomically: throws IoError, a std::runtime_error, naming the file).
// Library groups are written as references; their files are not touched.
void save_pxg(const Graph& g, const std::filesystem::path& file);

}  // namespace procex
