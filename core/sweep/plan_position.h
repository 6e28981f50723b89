// Positions as the sweep's error messages give them. The sweep works in a
// frame centred on the footprint (sweep.cc), so that a plan at x = 5e5 keeps
// its digits; a message names a point of the user's plan instead, as
// precisely as the sweep tells points apart.
#pragma once

#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace procex::engine {

struct PlanPosition {
  glm::dvec2 centre{0.0};   // the footprint's point at the frame's origin
  double resolution = 0.0;  // the clustering distance: finer digits are rounding (0: six significant digits)
  std::string operator()(glm::dvec2 local) const;
  std::string operator()(glm::dvec3 local) const;
};

}  // namespace procex::engine
