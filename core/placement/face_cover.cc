#include "core/placement/face_cover.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/geom/convex_clip.h"
#include "core/geom/nesting.h"

namespace procex {

FaceCover::FaceCover(const Mesh& mesh) {
  const auto edge_prop = source_edge_property(mesh);
  glm::dvec3 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (Mesh::VertexHandle v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    lo = glm::min(lo, glm::dvec3(p[0], p[1], p[2]));
    hi = glm::max(hi, glm::dvec3(p[0], p[1], p[2]));
  }
  plane_tolerance_ = mesh.n_vertices() ? kFacePlaneRelative * std::max(1.0, glm::length(hi - lo)) : 0.0;
  if (!edge_prop.is_valid()) return;
  for (Mesh::FaceHandle f : mesh.faces()) {
    std::vector<glm::dvec3> points;
    for (Mesh::VertexHandle v : mesh.fv_range(f)) {
      const auto& p = mesh.point(v);
      points.emplace_back(p[0], p[1], p[2]);
    }
    faces_[mesh.property(edge_prop, f)].push_back(std::move(points));
  }
}

std::vector<std::vector<glm::dvec2>> FaceCover::faces_in_plane(std::int32_t edge, const Frame& frame) const {
  std::vector<std::vector<glm::dvec2>> out;
  const auto it = faces_.find(edge);
  if (it == faces_.end()) return out;
  for (const std::vector<glm::dvec3>& face : it->second) {
    std::vector<glm::dvec2> flat;
    bool in_plane = true;
    for (const glm::dvec3& p : face) {
      const glm::dvec3 d = p - frame.origin;
      if (std::abs(glm::dot(d, frame.normal)) > plane_tolerance_) {
        in_plane = false;
        break;
      }
      flat.emplace_back(glm::dot(d, frame.along), glm::dot(d, frame.up));
    }
    if (in_plane && flat.size() >= 3) out.push_back(std::move(flat));
  }
  return out;
}

bool FaceCover::covers(std::int32_t edge, const Frame& frame, glm::dvec2 lo, glm::dvec2 hi) const {
  return covered(faces_in_plane(edge, frame), lo, hi);
}

bool covered(const std::vector<std::vector<glm::dvec2>>& faces, glm::dvec2 lo, glm::dvec2 hi) {
  const double area = (hi.x - lo.x) * (hi.y - lo.y);
  if (!(area > 0)) return false;
  double inside = 0;
  for (const std::vector<glm::dvec2>& face : faces) inside += area_inside(face, lo, hi);
  return inside >= area * (1 - kFaceCoverUncovered);
}

double area_inside(const std::vector<glm::dvec2>& polygon, glm::dvec2 lo, glm::dvec2 hi) {
  // Two buffers for the four clips, each allocated once: a convex polygon
  // gains at most a point a clip.
  std::vector<glm::dvec2> a, b;
  a.reserve(polygon.size() + 4);
  b.reserve(polygon.size() + 4);
  clip_to_half_plane(polygon, {1, 0}, -lo.x, 0, a);
  clip_to_half_plane(a, {-1, 0}, hi.x, 0, b);
  clip_to_half_plane(b, {0, 1}, -lo.y, 0, a);
  clip_to_half_plane(a, {0, -1}, hi.y, 0, b);
  return std::abs(twice_signed_area(b)) / 2;
}

}  // namespace procex
