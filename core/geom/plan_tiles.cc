#include "core/geom/plan_tiles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>

namespace procex {
namespace {

bool empty(const PlanBox& b) { return !(b.low.x <= b.high.x && b.low.y <= b.high.y); }

// A square grid over the data, its cells sized for `per_tile` box centres
// each on average. Cell coordinates are clamped to the grid, so a box reaching
// out of it lists itself in the border cells, as a query reaching out does.
class TileGrid {
 public:
  TileGrid(const PlanBox& all, std::size_t plans, std::size_t per_tile) : low_(all.low) {
    const glm::dvec2 size = all.high - all.low;
    const double tiles = std::max(1.0, static_cast<double>(plans) / static_cast<double>(std::max<std::size_t>(1, per_tile)));
    // Square cells of the data's area per tile, but no more along a side than
    // there are tiles (a long thin data set): at most 3 tiles + 1 cells in all.
    cell_ = std::max(std::sqrt(size.x * size.y / tiles), std::max(size.x, size.y) / tiles);
    if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = 1;  // every box in one point: one tile
    columns_ = cells_along(size.x, tiles), rows_ = cells_along(size.y, tiles);
  }
  std::size_t count() const { return columns_ * rows_; }
  std::size_t cell_of(glm::dvec2 p) const { return row(p.y) * columns_ + column(p.x); }
  // Calls visit for each cell the box (grown by reach) overlaps.
  template <class Visit>
  void cells(const PlanBox& b, double reach, Visit&& visit) const {
    const std::size_t c0 = column(b.low.x - reach), c1 = column(b.high.x + reach);
    const std::size_t r0 = row(b.low.y - reach), r1 = row(b.high.y + reach);
    for (std::size_t r = r0; r <= r1; ++r)
      for (std::size_t c = c0; c <= c1; ++c) visit(r * columns_ + c);
  }

 private:
  std::size_t cells_along(double extent, double tiles) const {
    return static_cast<std::size_t>(std::clamp(std::floor(extent / cell_) + 1, 1.0, tiles + 1));
  }
  std::size_t index(double v, double origin, std::size_t n) const {
    const double i = std::floor((v - origin) / cell_);
    return static_cast<std::size_t>(std::clamp(std::isnan(i) ? 0.0 : i, 0.0, static_cast<double>(n - 1)));
  }
  std::size_t column(double x) const { return index(x, low_.x, columns_); }
  std::size_t row(double y) const { return index(y, low_.y, rows_); }
  glm::dvec2 low_;
  double cell_ = 1;
  std::size_t columns_ = 1, rows_ = 1;
};

// Lists per cell, packed: the entries of cell c are at [start[c], start[c + 1]).
struct CellLists {
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> entries;
};

template <class ForEachEntry>
CellLists pack(std::size_t cells, ForEachEntry&& for_each_entry) {
  CellLists out;
  out.start.assign(cells + 1, 0);
  for_each_entry([&](std::size_t cell, std::uint32_t) { ++out.start[cell + 1]; });
  for (std::size_t c = 0; c < cells; ++c) out.start[c + 1] += out.start[c];
  out.entries.resize(out.start[cells]);
  std::vector<std::size_t> next(out.start.begin(), out.start.end() - 1);
  for_each_entry([&](std::size_t cell, std::uint32_t plan) { out.entries[next[cell]++] = plan; });
  return out;
}

}  // namespace

PlanBox plan_box(const std::vector<std::vector<glm::dvec2>>& loops) {
  PlanBox b{glm::dvec2(HUGE_VAL), glm::dvec2(-HUGE_VAL)};
  for (const auto& loop : loops)
    for (const glm::dvec2& p : loop) b.low = glm::min(b.low, p), b.high = glm::max(b.high, p);
  return b;
}

bool within(const PlanBox& a, const PlanBox& b, double reach) {
  return a.low.x - reach <= b.high.x && b.low.x <= a.high.x + reach && a.low.y - reach <= b.high.y &&
         b.low.y <= a.high.y + reach;
}

void for_each_plan_tile(const std::vector<PlanBox>& boxes, double reach, std::size_t per_tile,
                        const std::function<void(const PlanTile&)>& visit) {
  PlanBox all{glm::dvec2(HUGE_VAL), glm::dvec2(-HUGE_VAL)};
  std::size_t plans = 0;
  for (const PlanBox& b : boxes)
    if (!empty(b)) all.low = glm::min(all.low, b.low), all.high = glm::max(all.high, b.high), ++plans;
  if (plans == 0) return;
  const TileGrid grid(all, plans, per_tile);
  const auto n = static_cast<std::uint32_t>(boxes.size());
  // Each tile's own plans (by centre), and every plan listed in each cell its box grown by reach overlaps.
  const CellLists own = pack(grid.count(), [&](auto add) {
    for (std::uint32_t i = 0; i < n; ++i)
      if (!empty(boxes[i])) add(grid.cell_of((boxes[i].low + boxes[i].high) * 0.5), i);
  });
  const CellLists near = pack(grid.count(), [&](auto add) {
    for (std::uint32_t i = 0; i < n; ++i)
      if (!empty(boxes[i])) grid.cells(boxes[i], reach, [&](std::size_t cell) { add(cell, i); });
  });
  // A plan within reach of the tile's extent is listed in a cell the extent
  // overlaps (the point they share is in one): those cells' lists, each plan once.
  std::vector<std::uint32_t> seen(boxes.size(), 0);
  std::vector<std::size_t> tile_plans, others;
  std::uint32_t stamp = 0;
  for (std::size_t cell = 0; cell < grid.count(); ++cell) {
    if (own.start[cell] == own.start[cell + 1]) continue;
    ++stamp;
    PlanTile tile;
    tile.extent = {glm::dvec2(HUGE_VAL), glm::dvec2(-HUGE_VAL)};
    tile_plans.clear(), others.clear();
    for (std::size_t k = own.start[cell]; k < own.start[cell + 1]; ++k) {
      const std::uint32_t i = own.entries[k];
      tile_plans.push_back(i), seen[i] = stamp;
      tile.extent.low = glm::min(tile.extent.low, boxes[i].low), tile.extent.high = glm::max(tile.extent.high, boxes[i].high);
    }
    grid.cells(tile.extent, 0, [&](std::size_t c) {
      for (std::size_t k = near.start[c]; k < near.start[c + 1]; ++k)
        if (const std::uint32_t i = near.entries[k]; seen[i] != stamp && within(boxes[i], tile.extent, reach))
          others.push_back(i), seen[i] = stamp;
    });
    std::sort(others.begin(), others.end());
    tile.own = tile_plans.size();
    tile_plans.insert(tile_plans.end(), others.begin(), others.end());
    tile.plans = tile_plans;
    visit(tile);
  }
}

}  // namespace procex
