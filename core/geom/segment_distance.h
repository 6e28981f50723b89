// How far a point in the plan lies from a segment.
#pragma once

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace procex {

// The distance from p to the nearest point of the segment from a to b (to a
// where the segment has no length).
inline double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 d = b - a;
  const double len2 = glm::dot(d, d);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
  return glm::length(a + t * d - p);
}

}  // namespace procex
