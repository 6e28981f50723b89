// Boxes turned to the points they hold. An axis-aligned box of a long thin
// triangle that runs diagonally is mostly empty: the roof over a spiky plan
// is thousands of such slivers side by side, and their axis-aligned boxes
// all overlap one another, while boxes along their principal axes part
// every pair that does not come near.
#pragma once

#include <span>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace procex {

struct OrientedBox {
  glm::dvec3 centre{0.0};
  glm::dmat3 axes{1.0};  // orthonormal columns
  glm::dvec3 half{0.0};  // half the box's extent along each axis
};

// The box along the points' principal axes, grown by margin on every side
// and by enough more that rounding in its making and in oriented_overlap
// cannot part it from a box whose points come within the margins.
OrientedBox oriented_box_of(std::span<const glm::dvec3> points, double margin);

// False only when an axis parts the two boxes (the separating axis test over
// the 15 axes of two boxes).
bool oriented_overlap(const OrientedBox& a, const OrientedBox& b);

}  // namespace procex
