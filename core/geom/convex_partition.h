// Splitting a planar polygon with holes into convex polygons that use only its
// own vertices: the holes are bridged into the outer loop, the result is
// ear-clipped, and the triangles are merged back into convex pieces as long as
// they stay convex (Hertel-Mehlhorn), so the pieces are few and large.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

// loops[0] is the outer boundary, counter-clockwise; loops[1..] are holes,
// clockwise, inside it. A vertex is named by its position in the
// concatenation of the loops (loop 0's vertices first). Each piece is
// counter-clockwise and convex as is_convex() says; straight (collinear)
// vertices stay in the pieces, so neighbouring faces still share them. Best effort on invalid input
// (self-intersecting loops, holes outside): always terminates, every vertex
// of the input is used, but pieces may then overlap.
// Throws std::invalid_argument if a hole cannot be bridged (it is not inside the outer loop).
//
// work, if given, is told what the ear clipping did: tests hold it to bounds
// where a stopwatch could not.
struct PartitionWork {
  std::size_t ears_asked = 0;         // times a vertex was asked whether it is an ear
  std::size_t vertices_examined = 0;  // vertices those asks looked at
};
std::vector<std::vector<std::uint32_t>> convex_partition(const std::vector<std::vector<glm::dvec2>>& loops,
                                                         PartitionWork* work = nullptr);

// Whether a single loop (counter-clockwise) is convex: no clockwise turn and
// no reversal; straight vertices allowed, and so are vertices that turn
// clockwise by no more than kStraightTurnSine (straight up to the rounding of
// a rotated plan's coordinates), as in the pieces convex_partition returns.
bool is_convex(const std::vector<glm::dvec2>& loop);

}  // namespace procex
