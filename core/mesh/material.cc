#include "core/mesh/material.h"

#include <functional>
#include <limits>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>

namespace procex {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class Handle>
Handle find(const Mesh& mesh, const char* name) {
  Handle h;
  mesh.get_property_handle(h, name);
  return h;
}

template <class Handle, class T>
Handle add_filled(Mesh& mesh, const char* name, const T& fill) {
  Handle h = find<Handle>(mesh, name);
  if (h.is_valid()) return h;
  mesh.add_property(h, name);
  for (const auto e : mesh.halfedges()) mesh.property(h, e) = fill;
  return h;
}

}  // namespace

const Materials& materials_of(const MaterialTable& table) {
  static const Materials kNone;
  return table ? *table : kNone;
}

MaterialTable with_material(const MaterialTable& table, const std::string& tag, const Material& material) {
  // A batch passes every building's table through the same Material nodes:
  // each change is made once and its table shared by all of them, where a
  // copy per building and node cost a map of paths each (BENCHMARKS, Batch).
  // Keyed by the old table's address, held in the entry so no new table
  // takes it; looked up under a shared lock, so the workers' Material nodes
  // do not wait on each other.
  struct Change {
    const Materials* from;
    std::string tag;
    Material material;
    bool operator==(const Change&) const = default;
  };
  struct ChangeHash {
    std::size_t operator()(const Change& c) const {
      std::size_t h = std::hash<const Materials*>()(c.from);
      const auto mix = [&h](std::size_t v) { h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2); };
      // + 0.0: -0.0 equals 0.0, so it must hash alike.
      const auto number = [&mix](double v) { mix(std::hash<double>()(v + 0.0)); };
      mix(std::hash<std::string>()(c.tag));
      for (const double v : c.material.colour) number(v);
      number(c.material.roughness);
      number(c.material.metallic);
      mix(std::hash<std::filesystem::path::string_type>()(c.material.texture.native()));
      number(c.material.tile_size);
      return h;
    }
  };
  struct Made {
    MaterialTable from, to;
  };
  static std::shared_mutex mutex;
  static std::unordered_map<Change, Made, ChangeHash> made;
  constexpr std::size_t kKept = 256;  // a recipe's few nodes; a studio session's edits leave old ones behind
  Change change{table.get(), tag, material};
  {
    std::shared_lock lock(mutex);
    if (const auto it = made.find(change); it != made.end()) return it->second.to;
  }
  Materials materials = materials_of(table);
  materials[tag] = material;
  MaterialTable to = std::make_shared<const Materials>(std::move(materials));
  std::unique_lock lock(mutex);
  if (made.size() >= kKept) made.clear();
  // Another worker may have made the same change meanwhile: its table is the one shared.
  return made.try_emplace(std::move(change), Made{table, std::move(to)}).first->second.to;
}

MaterialTable material_table(Materials materials) {
  if (materials.empty()) return nullptr;
  return std::make_shared<const Materials>(std::move(materials));
}

FaceMaterials::FaceMaterials(const Mesh& mesh, const Materials& materials)
    : mesh_(mesh), materials_(materials), own_(find<OpenMesh::FPropHandleT<std::string>>(mesh, kFaceMaterialProperty)) {}

const Material* FaceMaterials::of(Mesh::FaceHandle f, const std::string& tag) const {
  if (materials_.empty()) return nullptr;
  const std::string& key = own_.is_valid() && !mesh_.property(own_, f).empty() ? mesh_.property(own_, f) : tag;
  const auto it = materials_.find(key);
  return it == materials_.end() ? nullptr : &it->second;
}

OpenMesh::FPropHandleT<std::string> add_face_materials(Mesh& mesh) {
  auto h = find<OpenMesh::FPropHandleT<std::string>>(mesh, kFaceMaterialProperty);
  if (!h.is_valid()) mesh.add_property(h, kFaceMaterialProperty);
  return h;
}

OpenMesh::HPropHandleT<OpenMesh::Vec2d> corner_uv_property(const Mesh& mesh) {
  return find<OpenMesh::HPropHandleT<OpenMesh::Vec2d>>(mesh, kCornerUvProperty);
}

OpenMesh::HPropHandleT<OpenMesh::Vec3d> corner_normal_property(const Mesh& mesh) {
  return find<OpenMesh::HPropHandleT<OpenMesh::Vec3d>>(mesh, kCornerNormalProperty);
}

OpenMesh::HPropHandleT<OpenMesh::Vec2d> add_corner_uvs(Mesh& mesh) {
  return add_filled<OpenMesh::HPropHandleT<OpenMesh::Vec2d>>(mesh, kCornerUvProperty, OpenMesh::Vec2d(kNaN, kNaN));
}

OpenMesh::HPropHandleT<OpenMesh::Vec3d> add_corner_normals(Mesh& mesh) {
  return add_filled<OpenMesh::HPropHandleT<OpenMesh::Vec3d>>(mesh, kCornerNormalProperty,
                                                               OpenMesh::Vec3d(kNaN, kNaN, kNaN));
}

}  // namespace procex
