// Planar polygons in 3D: their normal and a 2D view of them that keeps
// orientation, so 2D algorithms (convex partition) can work on them.
#pragma once

#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace procex {

// Newell's normal of a closed polygon: twice its vector area, so its length
// is twice the polygon's area and it points along the right-hand normal.
glm::dvec3 newell_normal(const std::vector<glm::dvec3>& points);

// The points seen along normal with its largest axis dropped, the remaining
// two axes ordered so that a loop counter-clockwise around normal stays
// counter-clockwise in 2D. Exact: coordinates are copied, not rotated.
std::vector<glm::dvec2> drop_axis(const std::vector<glm::dvec3>& points, const glm::dvec3& normal);
// The same into `out`, whose storage a caller of many faces keeps.
void drop_axis(const std::vector<glm::dvec3>& points, const glm::dvec3& normal, std::vector<glm::dvec2>& out);

}  // namespace procex
