// Clipping a polygon to a half-plane (one step of Sutherland-Hodgman): exact
// in topology for a convex polygon, so clipping by each side of a convex
// window in turn gives their intersection.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace procex {

// The part of `polygon` where dot(normal, p) + offset >= 0, in the same
// order; points where an edge crosses the line are interpolated along it.
// Empty if none of it is on that side. Points within `margin` of the line
// count as on it: kept, and no crossing is made between two of them (where
// the polygon runs along the line, rounding would otherwise put one anywhere
// along it).
std::vector<glm::dvec2> clip_to_half_plane(const std::vector<glm::dvec2>& polygon, glm::dvec2 normal, double offset,
                                           double margin = 0);
// The same into `out` (cleared first, its capacity kept), for callers that
// clip in turn between buffers they allocate once: growing a fresh vector
// point by point was most of what clipping a wall's tiles cost.
void clip_to_half_plane(const std::vector<glm::dvec2>& polygon, glm::dvec2 normal, double offset, double margin,
                        std::vector<glm::dvec2>& out);

// The part of `polygon` inside the counter-clockwise convex polygon `window`.
std::vector<glm::dvec2> clip_to_convex(std::vector<glm::dvec2> polygon, const std::vector<glm::dvec2>& window,
                                       double margin = 0);

}  // namespace procex
