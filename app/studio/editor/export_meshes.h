// export_meshes.h -- File > Export: the meshes the preview shows, written by
// the writer procex eval uses (nodes/support/mesh_export.h: .glb, .obj with
// its .mtl, .ply, .gpkg) and labelled as it labels them
// (nodes/support/mesh_labels.h), so a file the studio exports is the file
// `procex eval RECIPE -o FILE` writes for the same recipe.
#pragma once

#include <cstddef>
#include <filesystem>

#include "app/studio/editor/eval_worker.h"
#include "graph/graph.h"
#include "graph/status.h"
#include "nodes/support/mesh_export.h"

namespace procex::studio {

// Writes the meshes `shown` (an evaluation of `graph` as it is now) holds at
// the preview ports to `file`, in the format its extension names, atomically:
// with preview features (a footprint file given to the preview), every
// feature's buildings, labelled with its id and properties as procex batch
// labels them. Returns how many meshes were written, or why nothing was (no
// mesh evaluated, an unknown extension, a CRS a GeoPackage cannot take, a
// file that cannot be written).
Result<std::size_t> export_meshes(const Graph& graph, const EvalSnapshot& shown, const std::filesystem::path& file,
                                  const ExportOptions& options);

}  // namespace procex::studio
