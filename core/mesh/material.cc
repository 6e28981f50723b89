#include "core/mesh/material.h"

#include <limits>
#include <mutex>
#include <vector>

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
  // Keyed by the old table itself, held so no new one takes its address.
  struct Made {
    MaterialTable from;
    std::string tag;
    Material material;
    MaterialTable to;
  };
  static std::mutex mutex;
  static std::vector<Made> made;
  constexpr std::size_t kKept = 256;  // a recipe's few nodes; a studio session's edits leave old ones behind
  std::lock_guard lock(mutex);
  for (const Made& m : made)
    if (m.from == table && m.tag == tag && m.material == material) return m.to;
  Materials materials = materials_of(table);
  materials[tag] = material;
  if (made.size() >= kKept) made.clear();
  made.push_back({table, tag, material, std::make_shared<const Materials>(std::move(materials))});
  return made.back().to;
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
