#include "core/placement/cut_openings.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include <glm/geometric.hpp>

#include "core/geom/convex_partition.h"
#include "core/geom/error.h"
#include "core/geom/polygon3.h"
#include "core/placement/face_cover.h"

namespace procex {
namespace {

// Wall kept around an opening and between openings, relative to the mesh's
// bounding-box diagonal: a hole that meets its face's edge or another hole
// would leave a face of no width.
constexpr double kWallLeftRelative = 1e-4;

glm::dvec3 point(const Mesh& mesh, Mesh::VertexHandle v) {
  const auto& p = mesh.point(v);
  return {p[0], p[1], p[2]};
}

// A recess: the opening's rectangle on its face and the box it takes out of
// the solid behind it, in the frame's (along, up, normal) coordinates.
struct Recess {
  Frame frame;
  glm::dvec3 lo, hi;  // z from -depth to 0
  int face = -1;      // the face of the input mesh it is cut into

  glm::dvec3 local(const glm::dvec3& p) const {
    const glm::dvec3 d = p - frame.origin;
    return {glm::dot(d, frame.along), glm::dot(d, frame.up), glm::dot(d, frame.normal)};
  }
  glm::dvec3 world(double x, double y, double z) const {
    return frame.origin + x * frame.along + y * frame.up + z * frame.normal;
  }
  // Front corners (i < 4) counter-clockwise seen from outside, then the back ones behind them.
  glm::dvec3 corner(int i) const {
    const double x = i % 4 == 1 || i % 4 == 2 ? hi.x : lo.x, y = i % 4 >= 2 ? hi.y : lo.y;
    return world(x, y, i < 4 ? 0.0 : lo.z);
  }
  // Its six sides as world polygons.
  std::vector<std::vector<glm::dvec3>> sides() const {
    std::vector<std::vector<glm::dvec3>> out{{corner(0), corner(1), corner(2), corner(3)},
                                             {corner(4), corner(5), corner(6), corner(7)}};
    for (int i = 0; i < 4; ++i) out.push_back({corner(i), corner((i + 1) % 4), corner(4 + (i + 1) % 4), corner(4 + i)});
    return out;
  }
};

// Whether `polygon` (world) reaches into the box [lo, hi] of `r`'s
// coordinates: Sutherland-Hodgman against its six planes, exact for a
// planar polygon and a convex box.
bool reaches_into(const Recess& r, glm::dvec3 lo, glm::dvec3 hi, const std::vector<glm::dvec3>& polygon) {
  std::vector<glm::dvec3> p;
  for (const glm::dvec3& q : polygon) p.push_back(r.local(q));
  for (int axis = 0; axis < 3 && !p.empty(); ++axis)
    for (int side = 0; side < 2 && !p.empty(); ++side) {
      auto inside = [&](const glm::dvec3& q) { return side == 0 ? q[axis] - lo[axis] : hi[axis] - q[axis]; };
      std::vector<glm::dvec3> out;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec3 a = p[i], b = p[(i + 1) % p.size()];
        const double da = inside(a), db = inside(b);
        if (da > 0) out.push_back(a);
        if ((da > 0) != (db > 0)) out.push_back(a + da / (da - db) * (b - a));
      }
      p = std::move(out);
    }
  return !p.empty();
}

std::string describe(const Opening& o) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "opening %.3g x %.3g m on edge %d at (%.3f, %.3f, %.3f)", o.hi.x - o.lo.x, o.hi.y - o.lo.y,
                static_cast<int>(o.edge), o.frame.origin.x, o.frame.origin.y, o.frame.origin.z);
  return buf;
}

}  // namespace

Mesh cut_openings(const Mesh& mesh, const std::vector<std::string>& tags, const std::vector<Opening>& openings,
                  const CutSpec& spec, CutReport& report) {
  const auto edge_prop = source_edge_property(mesh);
  const auto kind_prop = face_kind_property(mesh);
  if (!edge_prop.is_valid() || !kind_prop.is_valid())
    throw MeshError("cut openings: the mesh carries no source edges (it was not made by Extrude)");
  if (tags.size() != mesh.n_faces()) throw MeshError("cut openings: the tags do not match the mesh's faces");
  glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (Mesh::VertexHandle v : mesh.vertices()) lo = glm::min(lo, point(mesh, v)), hi = glm::max(hi, point(mesh, v));
  const double gap = mesh.n_vertices() ? kWallLeftRelative * std::max(1.0, glm::length(hi - lo)) : 0.0;
  const double plane_tolerance = FaceCover(mesh).plane_tolerance();

  std::vector<std::vector<glm::dvec3>> faces(mesh.n_faces());
  std::map<std::int32_t, std::vector<int>> by_edge;
  for (Mesh::FaceHandle f : mesh.faces()) {
    for (Mesh::VertexHandle v : mesh.fv_range(f)) faces[f.idx()].push_back(point(mesh, v));
    by_edge[mesh.property(edge_prop, f)].push_back(f.idx());
  }

  std::vector<Recess> recesses;
  for (const Opening& o : openings) {
    Recess r{o.frame, {o.lo, -spec.depth}, {o.hi, 0.0}, -1};
    auto skip = [&](const std::string& why) { report.skipped.push_back(describe(o) + ": " + why); };
    if (!(r.hi.x - r.lo.x > 2 * gap && r.hi.y - r.lo.y > 2 * gap && spec.depth > gap)) {
      skip("too small to cut");
      continue;
    }
    // The one face of its edge, in its plane and facing its way, that holds it with wall left around.
    const glm::dvec2 grown_lo = o.lo - gap, grown_hi = o.hi + gap;
    for (int f : by_edge[o.edge]) {
      std::vector<glm::dvec2> flat;
      for (const glm::dvec3& p : faces[f]) {
        const glm::dvec3 q = r.local(p);
        if (std::abs(q.z) > plane_tolerance) break;
        flat.emplace_back(q.x, q.y);
      }
      if (flat.size() != faces[f].size() || glm::dot(newell_normal(faces[f]), o.frame.normal) <= 0) continue;
      if (covered({flat}, grown_lo, grown_hi)) r.face = f;
    }
    if (r.face < 0) {
      skip("not inside one face of its edge with wall left around it");
      continue;
    }
    bool clear = true;
    for (std::size_t f = 0; f < faces.size() && clear; ++f)
      if (reaches_into(r, r.lo + gap, r.hi - gap, faces[f])) {
        skip("its recess, " + std::to_string(spec.depth) + " m deep, would reach face " + std::to_string(f));
        clear = false;
      }
    for (std::size_t k = 0; k < recesses.size() && clear; ++k)
      for (const auto& side : recesses[k].sides())
        if (clear && reaches_into(r, r.lo - gap, r.hi + gap, side)) {
          skip("it overlaps or comes too near an opening cut before it");
          clear = false;
        }
    if (!clear) continue;
    recesses.push_back(r);
    ++report.cut;
  }

  Mesh out;
  add_face_properties(out);
  const auto out_edge = source_edge_property(out);
  const auto out_kind = face_kind_property(out);
  const auto out_tag = face_tag_property(out);
  for (Mesh::VertexHandle v : mesh.vertices()) out.add_vertex(mesh.point(v));
  std::vector<std::vector<const Recess*>> in_face(mesh.n_faces());
  for (const Recess& r : recesses) in_face[r.face].push_back(&r);
  std::vector<std::array<Mesh::VertexHandle, 8>> corners;  // per recess, in the order of `recesses`
  for (const Recess& r : recesses) {
    std::array<Mesh::VertexHandle, 8> c;
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 p = r.corner(i);
      c[i] = out.add_vertex({p.x, p.y, p.z});
    }
    corners.push_back(c);
  }
  auto add = [&](const std::vector<Mesh::VertexHandle>& loop, int source_edge, FaceKind kind, const std::string& tag) {
    const Mesh::FaceHandle f = out.add_face(loop);
    if (!f.is_valid()) throw MeshError("cut openings: OpenMesh refused a face of edge " + std::to_string(source_edge));
    out.property(out_edge, f) = source_edge;
    out.property(out_kind, f) = kind;
    out.property(out_tag, f) = tag;
  };
  for (Mesh::FaceHandle f : mesh.faces()) {
    const int edge = mesh.property(edge_prop, f);
    const FaceKind kind = mesh.property(kind_prop, f);
    std::vector<Mesh::VertexHandle> ids;
    for (Mesh::VertexHandle v : mesh.fv_range(f)) ids.push_back(v);
    if (in_face[f.idx()].empty()) {
      add(ids, edge, kind, tags[f.idx()]);
      continue;
    }
    // The face with its holes (clockwise seen from outside: front corners 0, 3, 2, 1), split into simple pieces.
    const glm::dvec3 normal = newell_normal(faces[f.idx()]);
    std::vector<std::vector<glm::dvec2>> flat{drop_axis(faces[f.idx()], normal)};
    for (const Recess* r : in_face[f.idx()]) {
      const auto& c = corners[r - recesses.data()];
      std::vector<glm::dvec3> hole;
      for (int i : {0, 3, 2, 1}) {
        ids.push_back(c[i]);
        hole.push_back(r->corner(i));
      }
      flat.push_back(drop_axis(hole, normal));
    }
    for (const auto& piece : convex_partition(flat)) {
      std::vector<Mesh::VertexHandle> loop;
      for (std::uint32_t i : piece) loop.push_back(ids[i]);
      add(loop, edge, kind, tags[f.idx()]);
    }
  }
  // Each hole edge a -> b of the face is met by a reveal b, a, a', b'; the back closes them.
  for (std::size_t k = 0; k < recesses.size(); ++k) {
    const auto& c = corners[k];
    const int edge = mesh.property(edge_prop, Mesh::FaceHandle(recesses[k].face));
    for (int i = 0; i < 4; ++i) {
      const int a = (4 - i) % 4, b = (3 - i) % 4;  // the hole's edges: 0 -> 3 -> 2 -> 1 -> 0
      add({c[b], c[a], c[a + 4], c[b + 4]}, edge, FaceKind::Side, spec.tag);
    }
    add({c[4], c[5], c[6], c[7]}, edge, FaceKind::Side, spec.tag);
  }
  return out;
}

}  // namespace procex
