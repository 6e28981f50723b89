#include "core/placement/placement_gltf.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/io/up_axis.h"

namespace procex {
namespace {

// A mesh's face tags as TaggedMeshView wants them: an index per face into
// the distinct tags; faces without a tag get `fallback`.
struct FaceTags {
  std::vector<std::uint32_t> of_face;
  std::vector<std::string> names;
};

FaceTags face_tags(const Mesh& mesh, const std::string& fallback) {
  FaceTags out;
  const auto prop = face_tag_property(mesh);
  for (const auto f : mesh.faces()) {
    const std::string& own = prop.is_valid() ? mesh.property(prop, f) : fallback;
    const std::string& tag = own.empty() ? fallback : own;
    auto it = std::find(out.names.begin(), out.names.end(), tag);
    if (it == out.names.end()) it = out.names.insert(out.names.end(), tag);
    out.of_face.push_back(static_cast<std::uint32_t>(it - out.names.begin()));
  }
  return out;
}

GltfMeshData gltf_mesh(const Mesh& mesh, const MaterialTable& materials, const std::string& name,
                       const std::string& fallback_tag, std::int64_t feature, const glm::dvec3& origin = {0, 0, 0}) {
  const FaceTags tags = face_tags(mesh, fallback_tag);
  return to_gltf_mesh({&mesh, tags.of_face, tags.names, name, feature, materials}, origin);
}

}  // namespace

GltfMeshData GltfPrototypeMemo::prototype(const PlaceableMesh& mesh) {
  const auto same = [&](const auto& held) {
    const PlaceableMesh& m = held.first;
    return m.mesh == mesh.mesh && m.name == mesh.name &&
           (m.materials == mesh.materials || materials_of(m.materials) == materials_of(mesh.materials));
  };
  {
    const std::lock_guard lock(mutex_);
    if (const auto it = std::find_if(converted_.begin(), converted_.end(), same); it != converted_.end()) return it->second;
  }
  GltfMeshData out = gltf_mesh(*mesh.mesh, mesh.materials, mesh.name, mesh.name, -1);
  const std::lock_guard lock(mutex_);
  if (converted_.size() < kCapacity && std::none_of(converted_.begin(), converted_.end(), same))
    converted_.emplace_back(mesh, out);
  return out;
}

GltfSceneBuilder::GltfSceneBuilder(std::shared_ptr<GltfPrototypeMemo> prototypes)
    : prototypes_(prototypes ? std::move(prototypes) : std::make_shared<GltfPrototypeMemo>()) {}

void GltfSceneBuilder::add(const PlacementResult& result, const std::string& building, std::int64_t feature) {
  for (std::size_t i = 0; i < result.instances.size(); ++i) check_instance(result, i);
  GltfMeshData data;
  if (result.building) data = gltf_mesh(*result.building, nullptr, building, "", feature, local_origin(*result.building));
  data.building = building;
  data.feature = feature;
  add(std::move(data));
  place(result);
}

void GltfSceneBuilder::add(GltfMeshData building) { scene_.meshes.push_back(std::move(building)); }

GltfMeshData& GltfSceneBuilder::last() {
  if (scene_.meshes.empty()) throw std::logic_error("GltfSceneBuilder: no building was added");
  return scene_.meshes.back();
}

void GltfSceneBuilder::place(const PlacementResult& placed) {
  GltfMeshData& data = last();
  for (std::size_t i = 0; i < placed.instances.size(); ++i) check_instance(placed, i);
  for (const Instance& in : placed.instances) {
    const PlaceableMesh& mesh = placed.meshes[in.mesh];
    // One prototype per mesh and look: a Material node gives the same shared
    // mesh another table, equal across buildings though not the same object.
    std::vector<std::pair<MaterialTable, std::size_t>>& looks = prototype_of_[mesh.mesh];
    auto it = std::find_if(looks.begin(), looks.end(),
                           [&](const auto& look) { return materials_of(look.first) == materials_of(mesh.materials); });
    if (it == looks.end()) {
      it = looks.insert(looks.end(), {mesh.materials, scene_.prototypes.size()});
      scene_.prototypes.push_back(prototypes_->prototype(mesh));
    }
    // Relative to the building's origin, as its node stands there.
    const glm::dmat4 from_origin = glm::translate(glm::dmat4(1.0), -glm::dvec3(data.origin[0], data.origin[1], data.origin[2]));
    data.instances.push_back({it->second, from_origin * to_file_axes(in.transform, UpAxis::Y), in.tag});
  }
}

}  // namespace procex
