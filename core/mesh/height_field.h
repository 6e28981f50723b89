// Whether a closed surface's triangles are proven to pass through none of
// each other, without comparing pairs: a roof over its flat base, seen from
// above, covers each point of the base once, and sheets that cover each
// point once cannot cross.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "core/mesh/mesh_triangle.h"

namespace procex {

// The last `slivers` of `triangles` are the validator's slivers, too thin for
// its pair search, which leaves them out: here they close the surface and
// the base, and which way they turn is not asked. The proof holds when
// - the triangles form a closed surface: each directed edge, between welded
//   vertices, is matched by as many running the other way;
// - every other triangle, seen from above, turns counter-clockwise (faces
//   up), clockwise (faces down) or neither (stands upright), and those facing
//   down lie in the plane of the lowest vertex, to the bit: the base;
// - the base's outline is loops that neither cross nor touch, each turning
//   clockwise at an even depth of nesting and counter-clockwise at an odd
//   one.
// Every turn is decided by exact predicates. Then no point of a triangle
// facing up lies inside another triangle facing up or the base's, and no
// triangle facing up reaches below the base: none of those pass through each
// other. Proof: a vertical line through a point x crosses a closed surface as
// often facing up as facing down (the signed count is the degree of the
// surface projected onto the plane, a 2-cycle there, so 0; upright triangles
// cover no area), so the triangles facing up cover x as often as the base
// does. The base's cover of x is minus the winding number of its outline
// about x, 0 or 1 by the nesting. Two triangles facing up with a common point
// inside one of them would cover the points round its shadow twice. Slivers,
// left out of the turns, move this only within their width, under the
// search's tolerance.
// Returns, where the proof holds, which of the triangles before the slivers
// it leaves to the search, each to be tested against every other: the
// upright ones (walls), whose shadow is a line. Nullopt: it does not hold,
// and every pair must be searched.
std::optional<std::vector<char>> proven_apart_over_base(const std::vector<MeshTriangle>& triangles,
                                                        std::size_t slivers);

}  // namespace procex
