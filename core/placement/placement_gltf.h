// Placement results into a glTF scene (core/io/gltf_write.h): the building as
// one mesh, each distinct placed mesh once as a prototype shared by every
// building added to the same builder, each instance as a node with its matrix.
// A prototype's primitives follow its faces' own tags (the mesh's name for
// faces without one); an instance's own tag goes into its node's extras.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/io/gltf_write.h"
#include "core/placement/placement.h"

namespace procex {

class GltfSceneBuilder {
 public:
  // Adds one building. Throws PlacementError (check_instance) for a bad instance.
  void add(const PlacementResult& result, const std::string& building, std::int64_t feature = -1);
  // Adds a building already in glTF form (to_gltf_mesh), without instances.
  void add(GltfMeshData building);
  // Adds placed's instances (its building mesh is not looked at) to the last
  // building added. Throws PlacementError (check_instance) for a bad instance,
  // std::logic_error if no building was added.
  void place(const PlacementResult& placed);
  // The last building added, to join more faces to it (append_to_gltf_mesh).
  // Throws std::logic_error if there is none.
  GltfMeshData& last();
  const GltfScene& scene() const { return scene_; }
  GltfScene take() && { return std::move(scene_); }

 private:
  GltfScene scene_;
  // Placed meshes already in scene_.prototypes, each mesh once per distinct
  // material table (held so no other mesh can come to live at the same
  // address).
  std::map<std::shared_ptr<const Mesh>, std::vector<std::pair<MaterialTable, std::size_t>>> prototype_of_;
};

}  // namespace procex
