#include "core/placement/facade_split.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/geom/polygon3.h"
#include "core/placement/face_cover.h"

namespace procex {

namespace {

// A face's normal within this of horizontal (sine of its tilt) counts as a wall.
constexpr double kVerticalSine = 1e-9;

struct Plane {
  std::int32_t edge;
  glm::dvec3 normal;  // horizontal, unit
  double offset;      // dot(normal, p) for p on the plane
  glm::dvec3 point;
};

}  // namespace

FacadeTiles split_facades(const Mesh& mesh, const std::function<bool(Mesh::FaceHandle)>& wall, const FacadeSplitSpec& spec) {
  const FaceCover cover(mesh);
  const double tol = cover.plane_tolerance();
  std::vector<Plane> planes;
  for (Mesh::FaceHandle f : mesh.faces()) {
    if (!wall(f)) continue;
    std::vector<glm::dvec3> points;
    for (Mesh::VertexHandle v : mesh.fv_range(f)) {
      const auto& p = mesh.point(v);
      points.emplace_back(p[0], p[1], p[2]);
    }
    glm::dvec3 n = newell_normal(points);
    const double length = glm::length(n);
    if (!(length > 0) || std::abs(n.z) > kVerticalSine * length) continue;
    n = glm::normalize(glm::dvec3(n.x, n.y, 0.0));
    const Plane plane{source_edge(mesh, f), n, glm::dot(n, points[0]), points[0]};
    const bool known = std::any_of(planes.begin(), planes.end(), [&](const Plane& q) {
      return q.edge == plane.edge && glm::dot(q.normal, n) > 1 - kVerticalSine && std::abs(q.offset - plane.offset) <= tol;
    });
    if (!known) planes.push_back(plane);
  }

  FacadeTiles out;
  const glm::dvec3 up(0.0, 0.0, 1.0);
  for (const Plane& plane : planes) {
    Frame frame;
    frame.normal = plane.normal;
    frame.up = up;
    frame.along = glm::cross(up, plane.normal);
    frame.origin = plane.point - plane.point.z * up;  // heights in the frame are world heights
    const std::vector<std::vector<glm::dvec2>> faces = cover.faces_in_plane(plane.edge, frame);
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    for (const auto& face : faces)
      for (const glm::dvec2& p : face) lo = glm::min(lo, p), hi = glm::max(hi, p);
    if (!(hi.x > lo.x) || !(hi.y > spec.z_from)) continue;
    const std::vector<SplitCell> floors = split_length(spec.floors, hi.y - spec.z_from);
    const std::vector<SplitCell> bays = split_length(spec.bays, hi.x - lo.x);
    for (const SplitCell& floor : floors) {
      const double z0 = spec.z_from + floor.start, z1 = z0 + floor.size;
      if (floor.index < 0 || z1 <= lo.y + tol || z0 >= hi.y - tol) continue;  // a gap, or not on this plane
      for (const SplitCell& bay : bays) {
        if (bay.index < 0) continue;
        const double u0 = lo.x + bay.start, u1 = u0 + bay.size;
        if (!covered(faces, {u0, z0}, {u1, z1})) {
          ++out.dropped;
          continue;
        }
        FacadeTile t{spec.name, plane.edge, frame, bay.size, floor.size, floor.index, bay.index};
        t.frame.origin = frame.origin + (u0 + u1) / 2 * frame.along + z0 * up;
        out.tiles.push_back(std::move(t));
      }
    }
  }
  return out;
}

}  // namespace procex
