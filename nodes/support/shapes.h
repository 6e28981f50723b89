// Parametric plan shapes for the Footprint Shape node: rectangles, L, T and U
// plans, a courtyard (a rectangle with a rectangular hole) and regular
// polygons. Each is centred on the origin, outer loop counter-clockwise, hole
// clockwise, so it feeds prepare_footprint() without repairs.
#pragma once

#include <string_view>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

struct ShapeSize {
  double width = 12.0;  // along x
  double depth = 10.0;  // along y
  double arm = 4.0;     // L/T/U: width of an arm; courtyard: thickness of the ring
  int sides = 6;        // ngon: number of sides (its circumradius is width / 2)
};

// shape: "rectangle", "l", "t", "u", "courtyard" or "ngon". Throws
// std::invalid_argument naming the parameter when the sizes cannot make the
// shape (an arm as wide as the plan, fewer than 3 sides...).
std::vector<std::vector<glm::dvec2>> make_shape(std::string_view shape, const ShapeSize& size);

}  // namespace procex
