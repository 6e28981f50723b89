// Whether a rectangle on a building's face lies wholly on the face: a facade
// tile or a placed window is kept only where the wall is really there under
// it, not above the roof line, not across a set-back (another plane), not past
// a corner (issue 15). The faces that count are those made from the anchor's
// footprint edge that lie in the anchor frame's plane.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/geom/anchor.h"
#include "core/mesh/mesh.h"

namespace procex {

// A face lies in a frame's plane when its vertices are within this (relative
// to the mesh's bounding-box diagonal) of the plane, and a rectangle is on the
// faces when they cover all but this fraction of its area (a window whose top
// meets the eaves exactly). Here rather than in core/geom/tolerances.h, which
// half the engine includes.
inline constexpr double kFacePlaneRelative = 1e-6;
inline constexpr double kFaceCoverUncovered = 1e-6;

class FaceCover {
 public:
  // Reads the faces of `mesh` once, grouped by source edge; the mesh must
  // outlive nothing (points are copied).
  explicit FaceCover(const Mesh& mesh);

  // True when the rectangle [lo, hi] in `frame`'s (along, up) coordinates
  // about its origin lies on the faces of footprint edge `edge` in the
  // frame's plane, to kFaceCoverUncovered of its area.
  bool covers(std::int32_t edge, const Frame& frame, glm::dvec2 lo, glm::dvec2 hi) const;

  // The faces of footprint edge `edge` in `frame`'s plane, as polygons in its
  // (along, up) coordinates about its origin (counter-clockwise seen from
  // outside).
  std::vector<std::vector<glm::dvec2>> faces_in_plane(std::int32_t edge, const Frame& frame) const;

  // How far from a plane a face's vertices may be and still lie in it.
  double plane_tolerance() const { return plane_tolerance_; }

 private:
  std::map<std::int32_t, std::vector<std::vector<glm::dvec3>>> faces_;  // by source edge
  double plane_tolerance_ = 0.0;
};

// Whether `faces` (polygons that do not overlap, as faces_in_plane gives
// them) cover the rectangle [lo, hi], to kFaceCoverUncovered of its area.
bool covered(const std::vector<std::vector<glm::dvec2>>& faces, glm::dvec2 lo, glm::dvec2 hi);

// The area of `polygon` (any simple polygon, either orientation) inside the
// rectangle [lo, hi]: Sutherland-Hodgman clipping, exact for a convex clip
// window whatever the polygon's shape.
double area_inside(const std::vector<glm::dvec2>& polygon, glm::dvec2 lo, glm::dvec2 hi);

}  // namespace procex
