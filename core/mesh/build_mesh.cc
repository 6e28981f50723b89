#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/geom/convex_partition.h"
#include "core/geom/error.h"
#include "core/geom/polygon3.h"
#include "core/mesh/mesh.h"

namespace procex {

namespace {

std::string list_text(const std::vector<std::uint32_t>& ids) {
  std::string out = "[";
  for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? ", " : "") + std::to_string(ids[i]);
  return out + "]";
}

std::string face_text(std::size_t index, const SurfaceFace& face) {
  return "face " + std::to_string(index) + " (" + face_kind_name(face.kind) + ", source edge " +
         std::to_string(face.source_edge) + ")";
}

// The face's loops with each hole that touches the outer loop at a vertex
// (the same id: a notch of the face whose tip is on its boundary, angles seed
// 75421) spliced into the outer loop there, which then passes that vertex
// twice, once on each side of the notch. Left a hole, its tip would be the
// outer loop's vertex again at the same point, and bridging it in makes
// pieces that pass the point twice.
std::vector<std::vector<std::uint32_t>> splice_touching_holes(const SurfaceFace& face) {
  std::vector<std::vector<std::uint32_t>> loops{face.loops[0]};
  for (std::size_t li = 1; li < face.loops.size(); ++li) {
    const auto& hole = face.loops[li];
    std::vector<std::uint32_t>& outer = loops[0];
    std::size_t at = outer.size(), from = 0;
    for (std::size_t k = 0; k < hole.size() && at == outer.size(); ++k) {
      at = static_cast<std::size_t>(std::find(outer.begin(), outer.end(), hole[k]) - outer.begin());
      from = k;
    }
    if (at == outer.size()) {
      loops.push_back(hole);
      continue;
    }
    std::vector<std::uint32_t> notch;
    for (std::size_t k = 1; k <= hole.size(); ++k) notch.push_back(hole[(from + k) % hole.size()]);
    outer.insert(outer.begin() + static_cast<std::ptrdiff_t>(at) + 1, notch.begin(), notch.end());
  }
  return loops;
}

// A face with holes, as simple planar polygons over its own vertex ids.
std::vector<std::vector<std::uint32_t>> split_face(const Surface& surface, std::size_t index, const SurfaceFace& face) {
  std::vector<glm::dvec3> outer;
  for (std::uint32_t v : face.loops[0]) outer.push_back(surface.vertices[v]);
  const glm::dvec3 normal = newell_normal(outer);
  std::vector<std::vector<glm::dvec2>> flat;
  std::vector<std::uint32_t> ids;
  for (const auto& loop : splice_touching_holes(face)) {
    std::vector<glm::dvec3> pts;
    for (std::uint32_t v : loop) pts.push_back(surface.vertices[v]);
    flat.push_back(drop_axis(pts, normal));
    ids.insert(ids.end(), loop.begin(), loop.end());
  }
  try {
    std::vector<std::vector<std::uint32_t>> pieces = convex_partition(flat);
    for (auto& piece : pieces)
      for (auto& v : piece) v = ids[v];
    return pieces;
  } catch (const std::invalid_argument& e) {
    throw MeshError(face_text(index, face) + " cannot be split into simple polygons: " + e.what());
  }
}

}  // namespace

const char* face_kind_name(FaceKind kind) {
  switch (kind) {
    case FaceKind::Base:
      return "base";
    case FaceKind::Side:
      return "side";
    case FaceKind::Cap:
      return "cap";
  }
  return "unknown";
}

OpenMesh::FPropHandleT<int> source_edge_property(const Mesh& mesh) {
  OpenMesh::FPropHandleT<int> h;
  mesh.get_property_handle(h, kSourceEdgeProperty);
  return h;
}

OpenMesh::FPropHandleT<FaceKind> face_kind_property(const Mesh& mesh) {
  OpenMesh::FPropHandleT<FaceKind> h;
  mesh.get_property_handle(h, kFaceKindProperty);
  return h;
}

OpenMesh::FPropHandleT<std::string> face_tag_property(const Mesh& mesh) {
  OpenMesh::FPropHandleT<std::string> h;
  mesh.get_property_handle(h, kFaceTagProperty);
  return h;
}

void add_face_properties(Mesh& mesh) {
  if (!face_tag_property(mesh).is_valid()) {
    OpenMesh::FPropHandleT<std::string> h;
    mesh.add_property(h, kFaceTagProperty);
  }
  if (!source_edge_property(mesh).is_valid()) {
    OpenMesh::FPropHandleT<int> h;
    mesh.add_property(h, kSourceEdgeProperty);
    for (const auto f : mesh.faces()) mesh.property(h, f) = -1;
  }
  if (!face_kind_property(mesh).is_valid()) {
    OpenMesh::FPropHandleT<FaceKind> h;
    mesh.add_property(h, kFaceKindProperty);
    for (const auto f : mesh.faces()) mesh.property(h, f) = FaceKind::Side;
  }
}

int source_edge(const Mesh& mesh, Mesh::FaceHandle f) {
  const auto h = source_edge_property(mesh);
  if (!h.is_valid()) throw MeshError("the mesh has no " + std::string(kSourceEdgeProperty) + " property");
  return mesh.property(h, f);
}

const std::string& face_tag(const Mesh& mesh, Mesh::FaceHandle f) {
  const auto h = face_tag_property(mesh);
  if (!h.is_valid()) throw MeshError("the mesh has no " + std::string(kFaceTagProperty) + " property");
  return mesh.property(h, f);
}

FaceKind face_kind(const Mesh& mesh, Mesh::FaceHandle f) {
  const auto h = face_kind_property(mesh);
  if (!h.is_valid()) throw MeshError("the mesh has no " + std::string(kFaceKindProperty) + " property");
  return mesh.property(h, f);
}

Mesh build_mesh(const Surface& surface) {
  Mesh mesh;
  add_face_properties(mesh);
  const auto edge_prop = source_edge_property(mesh);
  const auto kind_prop = face_kind_property(mesh);
  const auto tag_prop = face_tag_property(mesh);
  const std::size_t nv = surface.vertices.size();
  mesh.reserve(nv, nv + surface.faces.size(), surface.faces.size());
  for (std::size_t i = 0; i < nv; ++i) {
    const glm::dvec3& p = surface.vertices[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw MeshError("vertex " + std::to_string(i) + " has a non-finite coordinate");
    mesh.add_vertex({p.x, p.y, p.z});
  }

  std::vector<Mesh::VertexHandle> handles;
  for (std::size_t fi = 0; fi < surface.faces.size(); ++fi) {
    const SurfaceFace& face = surface.faces[fi];
    if (face.loops.empty()) throw MeshError(face_text(fi, face) + " has no loops");
    for (std::size_t li = 0; li < face.loops.size(); ++li) {
      const auto& loop = face.loops[li];
      if (loop.size() < 3)
        throw MeshError(face_text(fi, face) + ": loop " + std::to_string(li) + " has " + std::to_string(loop.size()) +
                        " vertices " + list_text(loop) + ", fewer than 3");
      for (std::uint32_t v : loop)
        if (v >= nv)
          throw MeshError(face_text(fi, face) + ": loop " + std::to_string(li) + " names vertex " + std::to_string(v) +
                          " but the surface has " + std::to_string(nv));
    }
    const std::vector<std::vector<std::uint32_t>> pieces =
        face.loops.size() == 1 ? face.loops : split_face(surface, fi, face);
    for (const auto& piece : pieces) {
      std::vector<std::uint32_t> sorted = piece;
      std::sort(sorted.begin(), sorted.end());
      if (const auto dup = std::adjacent_find(sorted.begin(), sorted.end()); dup != sorted.end())
        throw MeshError(face_text(fi, face) + " visits vertex " + std::to_string(*dup) + " twice: " + list_text(piece));
      handles.clear();
      for (std::uint32_t v : piece) handles.push_back(Mesh::VertexHandle(static_cast<int>(v)));
      const Mesh::FaceHandle f = mesh.add_face(handles);
      if (!f.is_valid())
        throw MeshError(face_text(fi, face) + ": OpenMesh refused the polygon " + list_text(piece) +
                        ": one of its edges already has a face on this side (a duplicate or flipped face, or a third "
                        "face at one edge), or one of its vertices is already closed around by other faces");
      mesh.property(edge_prop, f) = face.source_edge;
      mesh.property(kind_prop, f) = face.kind;
      mesh.property(tag_prop, f) = face.tag;
    }
  }
  return mesh;
}

}  // namespace procex
