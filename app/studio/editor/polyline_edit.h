// polyline_edit.h -- edits of a point-list parameter, shared by the plan
// editor (a closed footprint loop) and the profile editor (an open polyline
// in the (offset, height) plane that starts at (0, 0) and never goes down).
// Pure functions: the panel turns their results into set_param commands.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "graph/status.h"
#include "graph/value.h"

namespace procex::studio {

struct PolylineRules {
  bool closed = false;       // a loop: an edge from the last point back to the first
  bool monotone = false;     // heights (y) never decrease along the polyline
  bool pinned_start = false; // points[0] stays where it is (a profile's (0, 0))
  std::size_t min_points = 2;
};
inline constexpr PolylineRules kPlanRules{true, false, false, 3};
inline constexpr PolylineRules kProfileRules{false, true, true, 2};

// Moves point i towards `to`, as far as the rules allow: a monotone
// polyline's point keeps its height between its neighbours' heights; a pinned
// start does not move.
std::vector<Vec2> move_point(std::vector<Vec2> pts, std::size_t i, Vec2 to, const PolylineRules& rules);
// `to` for point i, with each coordinate within `tolerance` of a
// neighbour's moved onto it: the edge to that neighbour becomes exactly
// horizontal (a profile's soffit or ledge) or vertical (a wall, an
// axis-aligned plan edge).
Vec2 snap_to_neighbours(const std::vector<Vec2>& pts, std::size_t i, Vec2 to, double tolerance, bool closed);
// Inserts a point on edge e (between points e and e + 1), at `at` projected
// onto the edge so that a monotone polyline stays monotone.
std::vector<Vec2> insert_point(std::vector<Vec2> pts, std::size_t e, Vec2 at, const PolylineRules& rules);
// Refused (with the reason) below the minimum count or for a pinned start.
Result<std::vector<Vec2>> remove_point(std::vector<Vec2> pts, std::size_t i, const PolylineRules& rules);

// A profile's segment tags (one per segment) kept in step with its points:
// after insert_point on segment e both halves keep e's tag; after
// remove_point(i) the two segments meeting at i become one with the first
// one's tag. Tags that do not match the segment count are returned as they are.
std::vector<std::string> tags_after_insert(std::vector<std::string> tags, std::size_t segments, std::size_t e);
std::vector<std::string> tags_after_remove(std::vector<std::string> tags, std::size_t segments, std::size_t i);

// The point within `tolerance` of p, nearest first; nullopt if none.
std::optional<std::size_t> nearest_point(const std::vector<Vec2>& pts, Vec2 p, double tolerance);
// The edge within `tolerance` of p; nullopt if none.
std::optional<std::size_t> nearest_edge(const std::vector<Vec2>& pts, Vec2 p, double tolerance, bool closed);

}  // namespace procex::studio
