// Party walls found between footprints: a terrace of three houses in closed
// form, gaps within and beyond the distance, edges that only touch or cross.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/geom/party_walls.h"

namespace procex {
namespace {

PlanLoops rect(double x0, double y0, double x1, double y1) { return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}; }

using Ids = std::vector<std::int32_t>;

// Three 6 x 10 m houses side by side: edge 1 (east) of each meets edge 3
// (west) of the next, run the other way.
TEST(PartyWalls, ATerraceOfThree) {
  const auto party = party_edges({rect(0, 0, 6, 10), rect(6, 0, 12, 10), rect(12, 0, 18, 10)}, 0.3);
  EXPECT_EQ(party, (std::vector<Ids>{{1}, {1, 3}, {3}}));
}

TEST(PartyWalls, GapsWithinTheDistanceCount) {
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10), rect(6.2, 0, 12, 10)}, 0.3), (std::vector<Ids>{{1}, {3}}));
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10), rect(6.5, 0, 12, 10)}, 0.3), (std::vector<Ids>{{}, {}}));
}

// A neighbour 3 m deep beside a 10 m wall covers less than half of it; the
// neighbour's 3 m wall lies wholly along the longer one.
TEST(PartyWalls, AtLeastHalfTheEdgeMustBeShared) {
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10), rect(6, 0, 9, 3)}, 0.3), (std::vector<Ids>{{}, {3}}));
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10), rect(6, 0, 9, 6)}, 0.3), (std::vector<Ids>{{1}, {3}}));
}

// Corners that touch, a plan of two loops numbered across them, and one plan alone.
TEST(PartyWalls, TouchingCornersAndLoops) {
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10), rect(6, 10, 12, 20)}, 0.3), (std::vector<Ids>{{}, {}}));
  PlanLoops two = rect(0, 0, 6, 10);
  two.push_back(rect(20, 0, 26, 10)[0]);
  EXPECT_EQ(party_edges({two, rect(26, 0, 30, 10)}, 0.3), (std::vector<Ids>{{5}, {3}}));
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10)}, 0.3), (std::vector<Ids>{{}}));
}

// Neighbours face each other across the wall, whichever way their loops run;
// the same plan twice faces the same way and shares nothing. A courtyard's
// edges face a building standing in it.
TEST(PartyWalls, OnlyWallsThatFaceEachOther) {
  PlanLoops clockwise = rect(6, 0, 12, 10);
  std::reverse(clockwise[0].begin(), clockwise[0].end());  // from (6, 10): top, east, bottom, then west (id 3)
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10), clockwise}, 0.3), (std::vector<Ids>{{1}, {3}}));
  EXPECT_EQ(party_edges({rect(0, 0, 6, 10), rect(0, 0, 6, 10)}, 0.3), (std::vector<Ids>{{}, {}}));
  PlanLoops court = rect(0, 0, 30, 30);
  PlanLoops hole = rect(10, 10, 20, 20);
  std::reverse(hole[0].begin(), hole[0].end());
  court.push_back(hole[0]);
  EXPECT_EQ(party_edges({court, rect(10, 10, 20, 20)}, 0.3), (std::vector<Ids>{{4, 5, 6, 7}, {0, 1, 2, 3}}));
}

// Rotated by 30 degrees and far from the origin, and one very long edge among short ones.
TEST(PartyWalls, RotatedFarAndLong) {
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  auto turned = [&](PlanLoops p) {
    for (auto& loop : p)
      for (auto& q : loop) q = {4e5 + c * q.x - s * q.y, 5e6 + s * q.x + c * q.y};
    return p;
  };
  EXPECT_EQ(party_edges({turned(rect(0, 0, 6, 10)), turned(rect(6, 0, 12, 10))}, 0.3), (std::vector<Ids>{{1}, {3}}));
  std::vector<PlanLoops> row{rect(0, -5, 1000, 0)};
  for (int i = 0; i < 50; ++i) row.push_back(rect(20 * i, 0, 20 * i + 10, 10));
  const auto party = party_edges(row, 0.3);
  EXPECT_EQ(party[0], Ids{2});  // 500 m of its 1000 m top edge shared
  for (int i = 1; i <= 50; ++i) EXPECT_EQ(party[i], Ids{0}) << i;
}

}  // namespace
}  // namespace procex
