// How the loops of a footprint nest: which loop lies inside which.
#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace procex {

struct LoopNesting {
  std::vector<int> depth;   // number of other loops containing loop i
  std::vector<int> parent;  // the innermost loop containing loop i, or -1
};

// For loops that neither cross nor touch (prepare_footprint checks that).
// Even depth: material (outer boundaries, islands); odd depth: holes.
LoopNesting loop_nesting(const std::vector<std::vector<glm::dvec2>>& loops);

// Twice the signed area: positive for a counter-clockwise loop.
double twice_signed_area(const std::vector<glm::dvec2>& loop);

// Whether p lies inside loop (p must not lie on it); exact.
bool point_in_loop(const glm::dvec2& p, const std::vector<glm::dvec2>& loop);

}  // namespace procex
