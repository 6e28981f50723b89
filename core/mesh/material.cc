#include "core/mesh/material.h"

#include <limits>

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

const Materials& mesh_materials(const Mesh& mesh) {
  static const Materials kNone;
  const auto h = find<OpenMesh::MPropHandleT<Materials>>(mesh, kMaterialsProperty);
  return h.is_valid() ? mesh.property(h) : kNone;
}

void set_mesh_materials(Mesh& mesh, Materials materials) {
  auto h = find<OpenMesh::MPropHandleT<Materials>>(mesh, kMaterialsProperty);
  if (!h.is_valid()) mesh.add_property(h, kMaterialsProperty);
  mesh.property(h) = std::move(materials);
}

FaceMaterials::FaceMaterials(const Mesh& mesh)
    : mesh_(mesh), materials_(mesh_materials(mesh)), own_(find<OpenMesh::FPropHandleT<std::string>>(mesh, kFaceMaterialProperty)) {}

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
