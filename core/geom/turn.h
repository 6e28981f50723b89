// Walking a planar graph with the region kept on the left: at a vertex, the
// way on is the one that turns least clockwise from the way in, so where the
// boundary touches itself the walk stays on one simple loop.
#pragma once

#include <cmath>

#include <glm/vec2.hpp>

namespace procex {

// The clockwise angle, in (0, 2 pi], from `back` (the way in, reversed) to `out`.
inline double clockwise_turn(glm::dvec2 back, glm::dvec2 out) {
  double turn = std::atan2(back.y, back.x) - std::atan2(out.y, out.x);
  while (turn <= 0.0) turn += 2.0 * M_PI;
  while (turn > 2.0 * M_PI) turn -= 2.0 * M_PI;
  return turn;
}

}  // namespace procex
