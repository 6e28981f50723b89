// Placement results into a glTF scene (core/io/gltf_write.h): the building as
// one mesh, each distinct placed mesh once as a prototype shared by every
// building added to the same builder, each instance as a node with its matrix.
// A prototype's primitives follow its faces' own tags (the mesh's name for
// faces without one); an instance's own tag goes into its node's extras.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "core/io/gltf_write.h"
#include "core/placement/placement.h"

namespace procex {

// Placed meshes in glTF form (scene prototypes), each converted once for all
// the builders given this memo: a batch places the same few meshes (windows,
// doors, read once by Mesh Placement) on each of its buildings, and
// converting them again for each building's scene was a twentieth of a
// batch's CPU time (issue 18). Thread-safe. Holds at most kCapacity meshes,
// and each one it holds, so no other comes to live at its address; past that
// (a recipe making new meshes for each building) they are converted each time.
class GltfPrototypeMemo {
 public:
  static constexpr std::size_t kCapacity = 64;
  // The mesh in glTF form, its faces tagged by their own tags or its name.
  GltfMeshData prototype(const PlaceableMesh& mesh);

 private:
  std::mutex mutex_;
  std::vector<std::pair<PlaceableMesh, GltfMeshData>> converted_;
};

class GltfSceneBuilder {
 public:
  // `prototypes`: shared with other builders (a batch's); null: this builder's own.
  explicit GltfSceneBuilder(std::shared_ptr<GltfPrototypeMemo> prototypes = nullptr);
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
  std::shared_ptr<GltfPrototypeMemo> prototypes_;
  // Placed meshes already in scene_.prototypes, each mesh once per distinct
  // material table (held so no other mesh can come to live at the same
  // address).
  std::map<std::shared_ptr<const Mesh>, std::vector<std::pair<MaterialTable, std::size_t>>> prototype_of_;
};

}  // namespace procex
