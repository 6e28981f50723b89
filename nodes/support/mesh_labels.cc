#include "nodes/support/mesh_labels.h"

#include <cstdint>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace procex {

void label_parts(MeshSet& meshes, const GeoJsonFeature& f) {
  for (TaggedMesh& part : meshes.parts)
    part.building = f.id, part.feature = static_cast<std::int64_t>(f.index), part.properties = f.properties;
}

void label_parameters(MeshSet& meshes, const Graph& graph) {
  std::map<std::string, std::string> values;
  for (const ExposedParam& p : graph.exposed_params()) {
    const Value& v = graph.node(p.node)->params[p.param];
    if (!v || !v.type()->has_json()) continue;
    nlohmann::json j;
    v.type()->to_json(v.raw(), j);
    values[p.name] = j.dump();
  }
  for (TaggedMesh& part : meshes.parts) part.parameters = values;
}

}  // namespace procex
