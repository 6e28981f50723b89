// Plans in spatial tiles: a search whose answer for a plan depends only on
// what lies within some distance of it (party walls, street edges) runs tile
// by tile, so what it holds at once is a tile's plans and their neighbours',
// not every plan of a million-building file.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

// A plan's bounds (low > high on an axis: empty, the plan has no points).
struct PlanBox {
  glm::dvec2 low, high;
};

// The bounds of a plan's loops.
PlanBox plan_box(const std::vector<std::vector<glm::dvec2>>& loops);

// Whether a and b come within `reach` of each other (their boxes grown by it overlap).
bool within(const PlanBox& a, const PlanBox& b, double reach);

// The plans of one tile.
struct PlanTile {
  // The tile's own plans (by index into the boxes given), in index order,
  // then every other plan whose box comes within `reach` of `extent`, in
  // index order.
  std::span<const std::size_t> plans;
  std::size_t own = 0;  // how many of `plans` are the tile's own
  PlanBox extent;       // the bounds of the tile's own plans
};

// Puts each plan with a non-empty box in one tile (by its box's centre, tiles
// of about `per_tile` plans) and calls visit once per tile, in a fixed order.
// Plans with an empty box are in no tile. At most 2^32 - 1 plans.
void for_each_plan_tile(const std::vector<PlanBox>& boxes, double reach, std::size_t per_tile,
                        const std::function<void(const PlanTile&)>& visit);

}  // namespace procex
