#include "nodes/support/level_of_detail.h"

#include <memory>

#include "core/mesh/level_of_detail.h"

namespace procex {

MeshSet mesh_set_at_level_of_detail(const MeshSet& set, int level) {
  if (level >= 2) return set;
  MeshSet out;
  for (const TaggedMesh& part : set.parts) {
    auto mesh = std::make_shared<const Mesh>(level == 1 ? mean_height_block(*part.mesh) : footprint_mesh(*part.mesh));
    if (mesh->n_faces() == 0) continue;  // no footprint to stand on: a part placed or merged without one
    TaggedMesh& coarse = out.parts.emplace_back();
    coarse.building = part.building;
    coarse.feature = part.feature;
    coarse.properties = part.properties;
    coarse.parameters = part.parameters;
    coarse.mesh = std::move(mesh);
    face_tags_from_mesh(coarse);
  }
  return out;
}

}  // namespace procex
