// A footprint: closed loops in the plane, each edge carrying the angle its face
// leans at and an id that traces it into the output mesh.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/profile.h"

namespace procex {

// Angle in degrees from the vertical: 0 = vertical wall, positive leans inward
// like a roof, negative leans outward, +-90 = horizontal.
// With a profile (an index into Footprint::profiles), the edge follows it and
// angle_deg is not used.
struct EdgeSpec {
  double angle_deg = 45.0;
  std::int32_t id = -1;
  int profile = -1;

  bool operator==(const EdgeSpec&) const = default;
};

// Outer loops run counter-clockwise, holes clockwise, islands inside holes
// counter-clockwise again. The loop is implicitly closed: edges[k] runs from
// points[k] to points[(k + 1) % n], and edges.size() == points.size().
struct Loop {
  std::vector<glm::dvec2> points;
  std::vector<EdgeSpec> edges;
};

struct Footprint {
  std::vector<Loop> loops;
  std::vector<Profile> profiles;  // shared by the edges that name them
};

// Builds a footprint from plain loops, every edge at one angle, ids numbered
// 0, 1, 2, ... across the loops in order.
Footprint make_footprint(const std::vector<std::vector<glm::dvec2>>& loops, double angle_deg);

}  // namespace procex
