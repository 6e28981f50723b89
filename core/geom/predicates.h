// Exact geometric predicates on double coordinates. A fast floating-point
// filter decides almost every call; only near-degenerate cases fall back to
// exact arithmetic (error-free products and sums, Shewchuk's expansions), so
// "collinear" and "touching" mean exactly that, with no epsilon.
#pragma once

#include <glm/vec2.hpp>

namespace procex {

// +1 if a, b, c turn counter-clockwise, -1 if clockwise, 0 if collinear.
int orient2d(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c);

// Whether segments [a, b] and [c, d] share at least one point (touching counts).
bool segments_intersect(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d);

}  // namespace procex
