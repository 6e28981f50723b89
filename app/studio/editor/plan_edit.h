// plan_edit.h -- what the plan editor needs beyond moving points: a plan of
// an outer loop and an optional hole (Footprint Polygon's `points` and
// `hole`), checked by core's footprint rules so the editor can name the loop
// and vertex at fault, and a first hole placed well inside the outer loop.
// Pure functions: the panel turns their results into set_param commands.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "graph/value.h"

namespace procex::studio {

struct PlanIssue {
  std::string message;  // says which loop ("outer loop" or "hole") and vertex
  int loop = -1;        // 0 the outer loop, 1 the hole; -1 for the plan as a whole
  int vertex = -1;      // the vertex at fault, or -1
};

// Why the plan `outer` (+ `hole`, when not empty) would be refused by the
// sweep (core's prepare_footprint), or a hole not inside the outer loop;
// nullopt when it is usable.
std::optional<PlanIssue> check_plan(const std::vector<Vec2>& outer, const std::vector<Vec2>& hole);

// A small clockwise square well inside `outer` (near the point farthest from
// its edges), to start a hole from. Empty when `outer` has no inside.
std::vector<Vec2> hole_inside(const std::vector<Vec2>& outer);

}  // namespace procex::studio
