#include "core/mesh/uv_frames.h"

#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "core/geom/polygon3.h"
#include "core/geom/tolerances.h"

namespace procex {
namespace {

glm::dvec3 point(const Mesh& mesh, Mesh::VertexHandle v, const glm::dvec3& origin) {
  const Mesh::Point& p = mesh.point(v);
  return glm::dvec3(p[0], p[1], p[2]) - origin;
}

// Where a footprint edge starts, which way it runs in plan, and how far round
// its loop it starts: u = offset + (p - start) . direction.
struct EdgeRun {
  glm::dvec3 start;
  glm::dvec3 direction;
  double offset = 0;
};

// The footprint's edges as the base faces' border shows them: each border
// halfedge on the side face's side runs along its source edge the way the
// footprint does (counter-clockwise round outer loops seen from above).
// Loops are walked from their first border halfedge in mesh order, so the
// result is deterministic; an edge split into several pieces keeps the run
// of its first.
std::map<int, EdgeRun> footprint_runs(const Mesh& mesh, const glm::dvec3& origin) {
  std::map<int, EdgeRun> runs;
  const auto kind = face_kind_property(mesh);
  const auto edge = source_edge_property(mesh);
  if (!kind.is_valid() || !edge.is_valid()) return runs;
  // Border halfedge (side face's side) leaving each vertex.
  std::vector<Mesh::HalfedgeHandle> leaving(mesh.n_vertices());
  std::vector<Mesh::HalfedgeHandle> border;
  for (const auto h : mesh.halfedges()) {
    const auto f = mesh.face_handle(h), g = mesh.opposite_face_handle(h);
    if (!f.is_valid() || !g.is_valid()) continue;
    if (mesh.property(kind, g) != FaceKind::Base || mesh.property(kind, f) == FaceKind::Base) continue;
    Mesh::HalfedgeHandle& out = leaving[static_cast<std::size_t>(mesh.from_vertex_handle(h).idx())];
    if (!out.is_valid()) out = h;
    border.push_back(h);
  }
  std::vector<char> walked(mesh.n_halfedges(), 0);
  for (const auto first : border) {
    if (walked[static_cast<std::size_t>(first.idx())]) continue;
    double offset = 0;
    for (auto h = first;;) {
      walked[static_cast<std::size_t>(h.idx())] = 1;
      const glm::dvec3 a = point(mesh, mesh.from_vertex_handle(h), origin), b = point(mesh, mesh.to_vertex_handle(h), origin);
      glm::dvec3 d(b.x - a.x, b.y - a.y, 0.0);
      const double length = std::sqrt(d.x * d.x + d.y * d.y);
      const int e = mesh.property(edge, mesh.face_handle(h));
      if (length > 0 && e >= 0 && !runs.count(e)) runs[e] = {a, d / length, offset};
      offset += length;
      const Mesh::HalfedgeHandle next = leaving[static_cast<std::size_t>(mesh.to_vertex_handle(h).idx())];
      if (!next.is_valid() || walked[static_cast<std::size_t>(next.idx())]) break;
      h = next;
    }
  }
  return runs;
}

}  // namespace

glm::dvec2 UvFrame::at(const glm::dvec3& p) const {
  return {glm::dot(p, u) + offset.x, glm::dot(p, v) + offset.y};
}

std::vector<UvFrame> face_uv_frames(const Mesh& mesh, const glm::dvec3& origin) {
  const std::map<int, EdgeRun> runs = footprint_runs(mesh, origin);
  const auto edge = source_edge_property(mesh);
  std::vector<UvFrame> frames(mesh.n_faces());
  std::vector<glm::dvec3> pts;
  for (const auto f : mesh.faces()) {
    pts.clear();
    for (const auto v : mesh.fv_range(f)) pts.push_back(point(mesh, v, origin));
    glm::dvec3 n = newell_normal(pts);
    const double area2 = glm::length(n);
    UvFrame& frame = frames[static_cast<std::size_t>(f.idx())];
    if (!(area2 > 0)) continue;
    n /= area2;
    const double lean = std::sqrt(n.x * n.x + n.y * n.y);
    if (lean < SweepTolerances::parallel_sin) {
      if (n.z < 0) frame.v = {0, -1, 0};  // seen from below: (x, -y, down) is right-handed
      continue;
    }
    // Along the eave: the source edge's direction as it lies in the face
    // (the same on a face its edge swept, up to rounding), else the face's
    // own level line, e.g. on a face turned well away from its edge.
    glm::dvec3 d(-n.y / lean, n.x / lean, 0.0);
    const EdgeRun* run = nullptr;
    if (edge.is_valid())
      if (const auto it = runs.find(mesh.property(edge, f)); it != runs.end()) {
        const glm::dvec3 in_face = it->second.direction - glm::dot(it->second.direction, n) * n;
        if (glm::length(in_face) > 0.5) run = &it->second, d = glm::normalize(in_face);
      }
    const glm::dvec3 up = glm::normalize(glm::cross(n, d));
    glm::dvec3 lowest = pts[0];
    for (const glm::dvec3& p : pts)
      if (p.z < lowest.z) lowest = p;
    frame.u = d;
    frame.v = up;
    frame.offset = {run ? run->offset - glm::dot(run->start, d) : 0.0, lowest.z - glm::dot(lowest, up)};
  }
  return frames;
}

SurfaceAttributes surface_attributes(const Mesh& mesh, const glm::dvec3& origin) {
  const std::vector<UvFrame> frames = face_uv_frames(mesh, origin);
  const auto own_uv = corner_uv_property(mesh);
  const auto own_normal = corner_normal_property(mesh);
  SurfaceAttributes out;
  out.corner_uvs.reserve(mesh.n_halfedges() / 2);
  out.face_normals.reserve(mesh.n_faces());
  if (own_normal.is_valid()) out.corner_normals.reserve(mesh.n_halfedges() / 2);
  std::vector<glm::dvec3> pts;
  for (const auto f : mesh.faces()) {
    pts.clear();
    for (const auto v : mesh.fv_range(f)) pts.push_back(point(mesh, v, origin));
    const glm::dvec3 n = newell_normal(pts);
    const double len = glm::length(n);
    out.face_normals.push_back(len > 0 ? n / len : glm::dvec3(0, 0, 1));
    const UvFrame& frame = frames[static_cast<std::size_t>(f.idx())];
    std::size_t k = 0;
    for (const auto h : mesh.fh_range(f)) {
      const CornerAttribute own = corner_attribute(mesh, own_uv, own_normal, h);
      out.corner_uvs.push_back(own.uv ? *own.uv : frame.at(pts[k]));
      if (own_normal.is_valid()) out.corner_normals.push_back(own.normal ? *own.normal : out.face_normals.back());
      ++k;
    }
  }
  return out;
}

CornerAttribute corner_attribute(const Mesh& mesh, OpenMesh::HPropHandleT<OpenMesh::Vec2d> uv,
                                 OpenMesh::HPropHandleT<OpenMesh::Vec3d> normal, Mesh::HalfedgeHandle h) {
  CornerAttribute out;
  if (uv.is_valid())
    if (const OpenMesh::Vec2d& t = mesh.property(uv, h); std::isfinite(t[0]) && std::isfinite(t[1])) out.uv = glm::dvec2(t[0], t[1]);
  if (normal.is_valid())
    if (const OpenMesh::Vec3d& n = mesh.property(normal, h); std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]))
      out.normal = glm::dvec3(n[0], n[1], n[2]);
  return out;
}

}  // namespace procex
