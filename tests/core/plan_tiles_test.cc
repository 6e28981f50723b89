// The edge searches run tile by tile (core/geom/plan_tiles.h) give what one
// search over every plan gives: each plan owned by one tile, whose plans
// include every plan within reach of it, on rows of touching houses (party
// walls across tile borders), a plan spanning many tiles, and plans far apart.
#include "core/geom/plan_tiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "core/geom/party_walls.h"

namespace procex {
namespace {

PlanLoops rect(double x0, double y0, double x1, double y1) { return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}; }

// Rows of houses sharing walls (widths and depths drawn at random, some rows
// set back by up to 0.4 m, beyond the 0.3 m reach), a long building along the
// last row's backs, and a plan with no points.
std::vector<PlanLoops> town(int rows, int per_row, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> width(4, 12), setback(0, 0.4);
  std::vector<PlanLoops> plans;
  for (int r = 0; r < rows; ++r) {
    double x = 0;
    for (int k = 0; k < per_row; ++k) {
      const double w = width(rng), y = 30.0 * r + (k % 5 == 0 ? setback(rng) : 0);
      plans.push_back(rect(x, y, x + w, y + 10));
      x += w;
    }
  }
  plans.push_back(rect(0, 30.0 * (rows - 1) - 20, 12.0 * per_row, 30.0 * (rows - 1)));
  plans.push_back({});
  plans.push_back(rect(1e5, 1e5, 1e5 + 8, 1e5 + 8));
  return plans;
}

std::vector<std::vector<std::int32_t>> tiled_party_edges(const std::vector<PlanLoops>& plans, std::size_t per_tile,
                                                         std::vector<int>& owners) {
  std::vector<PlanBox> boxes;
  for (const PlanLoops& p : plans) boxes.push_back(plan_box(p));
  std::vector<std::vector<std::int32_t>> out(plans.size());
  owners.assign(plans.size(), 0);
  for_each_plan_tile(boxes, 0.3, per_tile, [&](const PlanTile& tile) {
    std::vector<PlanLoops> mine;
    for (const std::size_t i : tile.plans) mine.push_back(plans[i]);
    const auto ids = party_edges(mine, 0.3);
    for (std::size_t k = 0; k < tile.own; ++k) out[tile.plans[k]] = ids[k], ++owners[tile.plans[k]];
  });
  return out;
}

TEST(PlanTiles, TileByTileGivesTheWholeSearchsPartyWalls) {
  const std::vector<PlanLoops> plans = town(12, 40, 18);
  const auto whole = party_edges(plans, 0.3);
  std::size_t shared = 0;
  for (const auto& ids : whole) shared += ids.size();
  ASSERT_GT(shared, 800u);  // the rows' walls, and the long building's back
  for (const std::size_t per_tile : {1, 7, 50, 100000}) {
    std::vector<int> owners;
    EXPECT_EQ(tiled_party_edges(plans, per_tile, owners), whole) << per_tile;
    for (std::size_t i = 0; i < plans.size(); ++i) EXPECT_EQ(owners[i], plans[i].empty() ? 0 : 1) << i << " " << per_tile;
  }
}

// Every plan in one point, and plans on one line: one tile, or tiles along it.
TEST(PlanTiles, DegenerateExtents) {
  std::vector<PlanBox> boxes(5, PlanBox{{2, 3}, {2, 3}});
  int tiles = 0;
  for_each_plan_tile(boxes, 0.3, 1, [&](const PlanTile& t) {
    ++tiles;
    EXPECT_EQ(t.plans.size(), 5u);
  });
  EXPECT_EQ(tiles, 1);
  boxes.clear();
  for (int i = 0; i < 100; ++i) boxes.push_back({{i * 10.0, 0}, {i * 10.0 + 10, 0}});
  std::vector<int> owned(boxes.size(), 0);
  for_each_plan_tile(boxes, 0.3, 10, [&](const PlanTile& t) {
    EXPECT_LE(t.plans.size(), 30u);
    for (std::size_t k = 0; k < t.own; ++k) ++owned[t.plans[k]];
    for (std::size_t k = 0; k < t.own; ++k)  // the neighbours either side are there
      for (const std::size_t neighbour : {t.plans[k] - 1, t.plans[k] + 1}) {
        if (neighbour >= boxes.size()) continue;
        EXPECT_NE(std::find(t.plans.begin(), t.plans.end(), neighbour), t.plans.end());
      }
  });
  EXPECT_EQ(owned, std::vector<int>(boxes.size(), 1));
}

}  // namespace
}  // namespace procex
