// plan_edit.h -- what the plan editor needs beyond moving points: a plan of
// an outer loop and any number of holes (Footprint Polygon's `points` and
// `holes`), checked by core's footprint rules so the editor can name the loop
// and vertex at fault, and a new hole placed well inside the outer loop and
// clear of the other holes.
// Pure functions: the panel turns their results into set_param commands.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "graph/value.h"

namespace procex::studio {

struct PlanIssue {
  std::string message;  // says which loop ("outer loop" or "hole K", from 1) and vertex
  int loop = -1;        // 0 the outer loop, K hole K; -1 for the plan as a whole
  int vertex = -1;      // the vertex at fault, or -1
};

using PlanLoops = std::vector<std::vector<Vec2>>;

// Why the plan `outer` with `holes` would be refused by the sweep (core's
// prepare_footprint), or a hole not inside the outer loop, or inside another
// hole; nullopt when it is usable.
std::optional<PlanIssue> check_plan(const std::vector<Vec2>& outer, const PlanLoops& holes);

// A small clockwise square well inside `outer` and clear of `holes` (near the
// point farthest from every edge), to start a hole from. Empty when there is
// no room.
std::vector<Vec2> hole_inside(const std::vector<Vec2>& outer, const PlanLoops& holes = {});

}  // namespace procex::studio
