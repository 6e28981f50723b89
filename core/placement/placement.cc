#include "core/placement/placement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/geom/error.h"
#include "core/placement/placement_error.h"
#include "core/geom/tolerances.h"
#include "core/mesh/material.h"

namespace procex {

double linear_determinant(const glm::dmat4& transform) { return glm::determinant(glm::dmat3(transform)); }

std::size_t PlacementResult::add_mesh(const PlaceableMesh& mesh) {
  if (!mesh.mesh) throw PlacementError("the mesh '" + mesh.name + "' to place is null");
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (meshes[i].mesh == mesh.mesh && meshes[i].name == mesh.name &&
        materials_of(meshes[i].materials) == materials_of(mesh.materials))
      return i;
  meshes.push_back(mesh);
  return meshes.size() - 1;
}

std::size_t PlacementResult::add_instance(Instance instance) {
  if (instances.size() >= kMaxInstancesPerBuilding)
    throw PlacementError("the building would get more than " + std::to_string(kMaxInstancesPerBuilding) +
                         " placed meshes, more than one building can hold: place fewer (a larger spacing, fewer rows "
                         "or columns)");
  instances.push_back(std::move(instance));
  try {
    check_instance(*this, instances.size() - 1);
  } catch (...) {
    instances.pop_back();
    throw;
  }
  const std::size_t faces = meshes[instances.back().mesh].mesh->n_faces();
  if (faces > kMaxPlacedFacesPerBuilding - placed_faces) {
    instances.pop_back();
    throw PlacementError("the building's placed meshes would have more than " + std::to_string(kMaxPlacedFacesPerBuilding) +
                         " faces (" + std::to_string(instances.size()) + " placed so far): place fewer, or a simpler mesh");
  }
  placed_faces += faces;
  return instances.size() - 1;
}

std::string transform_problem(const glm::dmat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return "a non-finite transform";
  if (m[0][3] != 0.0 || m[1][3] != 0.0 || m[2][3] != 0.0 || m[3][3] != 1.0)
    return "a projective transform: its last row must be 0 0 0 1";
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) largest = std::max(largest, glm::length(glm::dvec3(m[c])));
  if (!(std::abs(linear_determinant(m)) > kSingularDeterminantRelative * largest * largest * largest))
    return "a singular transform: it would collapse the mesh";
  return {};
}

void check_instance(const PlacementResult& result, std::size_t index) {
  const Instance& in = result.instances.at(index);
  const std::string name = "instance " + std::to_string(index);
  if (in.mesh >= result.meshes.size() || !result.meshes[in.mesh].mesh)
    throw PlacementError(name + " names mesh " + std::to_string(in.mesh) + " but there are " +
                         std::to_string(result.meshes.size()));
  if (const std::string problem = transform_problem(in.transform); !problem.empty())
    throw PlacementError(name + " (" + result.meshes[in.mesh].name + ") has " + problem);
}

namespace {

// The placed meshes' corner attributes on `out` (NaN on the building's own
// faces) where any of them has some.
struct CornerAttributes {
  OpenMesh::HPropHandleT<OpenMesh::Vec2d> uv;
  OpenMesh::HPropHandleT<OpenMesh::Vec3d> normal;
};

CornerAttributes prepare_corner_attributes(Mesh& out, const PlacementResult& result) {
  CornerAttributes a;
  for (const Instance& in : result.instances) {
    const Mesh& mesh = *result.meshes[in.mesh].mesh;
    if (corner_uv_property(mesh).is_valid() && !a.uv.is_valid()) a.uv = add_corner_uvs(out);
    if (corner_normal_property(mesh).is_valid() && !a.normal.is_valid()) a.normal = add_corner_normals(out);
  }
  return a;
}

// Face g of `out` takes the corner attributes of face f of `mesh`, placed by
// `transform` (normals by its inverse transpose); handles[i] is the vertex of
// out that mesh's vertex i became.
void copy_corner_attributes(Mesh& out, const CornerAttributes& to, Mesh::FaceHandle g, const Mesh& mesh,
                            Mesh::FaceHandle f, const std::vector<Mesh::VertexHandle>& handles, const glm::dmat3& normal_matrix) {
  const auto uv = corner_uv_property(mesh);
  const auto normal = corner_normal_property(mesh);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (const auto h : out.fh_range(g)) {
    OpenMesh::Vec2d t(kNaN, kNaN);
    OpenMesh::Vec3d n(kNaN, kNaN, kNaN);
    for (const auto k : mesh.fh_range(f)) {
      if (handles[static_cast<std::size_t>(mesh.to_vertex_handle(k).idx())] != out.to_vertex_handle(h)) continue;
      if (uv.is_valid()) t = mesh.property(uv, k);
      if (normal.is_valid()) {
        const OpenMesh::Vec3d& m = mesh.property(normal, k);
        const glm::dvec3 q = glm::normalize(normal_matrix * glm::dvec3(m[0], m[1], m[2]));
        n = {q.x, q.y, q.z};  // NaN stays NaN
      }
    }
    if (to.uv.is_valid()) out.property(to.uv, h) = t;
    if (to.normal.is_valid()) out.property(to.normal, h) = n;
  }
}

}  // namespace

Mesh flatten(const PlacementResult& result) {
  Mesh out;
  if (result.building) out = *result.building;
  add_face_properties(out);
  OpenMesh::FPropHandleT<int> instance_prop;
  if (!out.get_property_handle(instance_prop, kInstanceProperty)) {
    out.add_property(instance_prop, kInstanceProperty);
    for (const auto f : out.faces()) out.property(instance_prop, f) = -1;
  }
  const auto tag_prop = face_tag_property(out);
  const auto edge_prop = source_edge_property(out);
  const auto kind_prop = face_kind_property(out);
  const CornerAttributes corners = prepare_corner_attributes(out, result);
  OpenMesh::FPropHandleT<std::string> material_prop;  // added with the first face that needs it

  std::vector<Mesh::VertexHandle> handles, face;
  for (std::size_t i = 0; i < result.instances.size(); ++i) {
    check_instance(result, i);
    const Instance& in = result.instances[i];
    const PlaceableMesh& placed = result.meshes[in.mesh];
    const Mesh& mesh = *placed.mesh;
    const auto own_tags = face_tag_property(mesh);
    const bool mirrored = linear_determinant(in.transform) < 0.0;
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(in.transform)));
    handles.clear();
    for (const auto v : mesh.vertices()) {
      const Mesh::Point& p = mesh.point(v);
      const glm::dvec4 q = in.transform * glm::dvec4(p[0], p[1], p[2], 1.0);
      handles.push_back(out.add_vertex({q.x, q.y, q.z}));
    }
    for (const auto f : mesh.faces()) {
      face.clear();
      for (const auto v : mesh.fv_range(f)) face.push_back(handles[static_cast<std::size_t>(v.idx())]);
      if (mirrored) std::reverse(face.begin(), face.end());
      const Mesh::FaceHandle g = out.add_face(face);
      if (!g.is_valid())
        throw MeshError("instance " + std::to_string(i) + " (" + placed.name + "): OpenMesh refused its face " +
                        std::to_string(f.idx()));
      const std::string* own = own_tags.is_valid() ? &mesh.property(own_tags, f) : nullptr;
      const std::string& own_tag = own && !own->empty() ? *own : placed.name;
      out.property(tag_prop, g) = !in.tag.empty() ? in.tag : own_tag;
      // Tagged otherwise, the face keeps its own material (a Material naming
      // the instance's tag made its mesh's faces that tag's: nodes/material.cc).
      if (!in.tag.empty() && own_tag != in.tag && materials_of(placed.materials).count(own_tag)) {
        if (!material_prop.is_valid()) material_prop = add_face_materials(out);
        out.property(material_prop, g) = own_tag;
      }
      out.property(edge_prop, g) = in.source_edge;
      out.property(kind_prop, g) = FaceKind::Side;
      out.property(instance_prop, g) = static_cast<int>(i);
      if (corners.uv.is_valid() || corners.normal.is_valid())
        copy_corner_attributes(out, corners, g, mesh, f, handles, normal_matrix);
    }
  }
  return out;
}

MaterialTable flattened_materials(const MaterialTable& building, const PlacementResult& result) {
  Materials materials = materials_of(building);
  bool added = false;
  for (const Instance& in : result.instances)
    for (const auto& [tag, material] : materials_of(result.meshes[in.mesh].materials))
      added = materials.try_emplace(tag, material).second || added;
  return added ? material_table(std::move(materials)) : building;
}

}  // namespace procex
