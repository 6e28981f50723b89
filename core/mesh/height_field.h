// Whether a closed surface's triangles are proven to pass through none of
// each other, without comparing pairs: a roof over its flat base, seen from
// above, covers each point of the base once, and sheets that cover each
// point once cannot cross.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh/mesh_triangle.h"

namespace procex {

// The last `slivers` of `triangles` are the validator's slivers, too thin for
// its pair search, which leaves them out: here they close the surface and
// the base, and may turn either way by a hundredth of `tolerance` (or their
// coordinates' rounding), but not fold back by more. The proof holds when
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
// inside one of them would cover the points round its shadow twice. Slivers
// turning clockwise move this only within their fold.
// Upright triangles (walls) cover no area seen from above: the proof leaves
// them to the search. One standing on an edge of the base's outline, its
// shadow that edge, is reached by nothing facing up or down: the base covers
// one side of the edge and nothing the other, and a triangle passing through
// the wall would cover points on both; and walls on two edges of the outline
// meet at most above a corner they share, at their sides. Such a wall needs
// comparing only with the walls on its own edge; but where another edge of
// the outline that does not meet its own comes nearer than `tolerance`, it
// is compared with every triangle, since the pair search takes what is apart
// by less than its tolerance as touching (walls either side of a Z-fold of
// the plan, facing one way, which it finds overlapping).
constexpr std::uint32_t kCovered = 0xffffffffu;  // facing up or down: crosses no covered triangle
constexpr std::uint32_t kUpright = 0xfffffffeu;  // every pair with it is searched

// Where the proof holds, how it leaves each triangle before the slivers to
// the search: kCovered, kUpright, or, for a wall on the base's outline, the
// number of its outline edge, whose walls are to be compared with each
// other. Nullopt where the proof does not hold, and every pair must be
// searched.
std::optional<std::vector<std::uint32_t>> proven_apart_over_base(const std::vector<MeshTriangle>& triangles,
                                                                 std::size_t slivers, double tolerance);

}  // namespace procex
