#include "app/studio/editor/export_meshes.h"

#include <exception>

#include "nodes/support/mesh_labels.h"

namespace procex::studio {

Result<std::size_t> export_meshes(const Graph& graph, const EvalSnapshot& shown, const std::filesystem::path& file,
                                  const ExportOptions& options) {
  MeshSet meshes;
  for (const MeshSet& m : shown.feature_meshes) meshes.parts.insert(meshes.parts.end(), m.parts.begin(), m.parts.end());
  if (shown.features == 0)
    for (const PortRef& p : preview_ports(graph))
      if (auto it = shown.values.find(p); it != shown.values.end())
        if (const MeshSet* m = it->second.get_if<MeshSet>()) meshes.parts.insert(meshes.parts.end(), m->parts.begin(), m->parts.end());
  if (meshes.parts.empty()) return Status::error("nothing to export: the recipe has no evaluated mesh");
  label_parameters(meshes, graph);
  try {
    write_mesh_set(file, meshes, options);
  } catch (const std::exception& e) {
    return Status::error(e.what());
  }
  return meshes.parts.size();
}

}  // namespace procex::studio
