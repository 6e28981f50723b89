#include "core/mesh/level_of_detail.h"

#include <algorithm>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/geom/polygon3.h"
#include "core/mesh/validate.h"

namespace procex {
namespace {

// The building's Base faces as a surface of their own, with the edges of their
// outline (those no other Base face shares) as the faces run them.
struct Base {
  Surface surface;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> outline;
  double area = 0.0;
  double ground = std::numeric_limits<double>::infinity();
};

Base base_of(const Mesh& building) {
  Base base;
  const auto kinds = face_kind_property(building);
  if (!kinds.is_valid()) return base;
  const auto is_base = [&](Mesh::FaceHandle f) { return f.is_valid() && building.property(kinds, f) == FaceKind::Base; };
  std::unordered_map<int, std::uint32_t> index;  // the building's vertex -> the surface's
  const auto vertex = [&](Mesh::VertexHandle v) {
    const auto [it, added] = index.try_emplace(v.idx(), static_cast<std::uint32_t>(base.surface.vertices.size()));
    if (added) {
      const Mesh::Point& p = building.point(v);
      base.surface.vertices.emplace_back(p[0], p[1], p[2]);
      base.ground = std::min(base.ground, p[2]);
    }
    return it->second;
  };
  for (const auto f : building.faces()) {
    if (!is_base(f)) continue;
    SurfaceFace& face = base.surface.faces.emplace_back();
    face.kind = FaceKind::Base;
    face.tag = "base";
    std::vector<std::uint32_t>& loop = face.loops.emplace_back();
    std::vector<glm::dvec3> points;
    for (const auto h : building.fh_range(f)) {
      loop.push_back(vertex(building.from_vertex_handle(h)));
      points.push_back(base.surface.vertices[loop.back()]);
      if (!is_base(building.face_handle(building.opposite_halfedge_handle(h))))
        base.outline.emplace_back(loop.back(), vertex(building.to_vertex_handle(h)));
    }
    base.area -= newell_normal(points).z / 2.0;  // facing down: the normal's z is minus twice the area
  }
  return base;
}

}  // namespace

Mesh footprint_mesh(const Mesh& building) {
  Base base = base_of(building);
  for (SurfaceFace& face : base.surface.faces) {
    std::reverse(face.loops[0].begin(), face.loops[0].end());
    face.tag = "footprint";
  }
  return build_mesh(base.surface);
}

double mean_height(const Mesh& building) {
  const Base base = base_of(building);
  return base.area > 0.0 ? signed_volume(building) / base.area : 0.0;
}

Mesh mean_height_block(const Mesh& building) {
  Base base = base_of(building);
  if (base.surface.faces.empty()) return build_mesh(base.surface);
  const double top = base.ground + signed_volume(building) / base.area;
  Surface& s = base.surface;
  const auto n = static_cast<std::uint32_t>(s.vertices.size());
  for (std::uint32_t i = 0; i < n; ++i) s.vertices.emplace_back(s.vertices[i].x, s.vertices[i].y, top);
  const std::size_t base_faces = s.faces.size();
  for (std::size_t f = 0; f < base_faces; ++f) {
    SurfaceFace cap{FaceKind::Cap, -1, {{}}, "roof"};
    for (auto it = s.faces[f].loops[0].rbegin(); it != s.faces[f].loops[0].rend(); ++it) cap.loops[0].push_back(*it + n);
    s.faces.push_back(std::move(cap));
  }
  // The base faces run clockwise seen from above (they face down), so an
  // outline edge a -> b, then up, is outward.
  for (const auto& [a, b] : base.outline) s.faces.push_back(SurfaceFace{FaceKind::Side, -1, {{a, a + n, b + n, b}}, "wall"});
  return build_mesh(s);
}

}  // namespace procex
