// The plan's cross product: positive where b turns counter-clockwise from a.
#pragma once

#include <glm/vec2.hpp>

namespace procex {

inline double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

}  // namespace procex
