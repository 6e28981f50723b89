// Plan and profile editing rules: monotone profiles while dragging, a pinned
// (0, 0) start, minimum point counts, hit tests on points and edges.
#include "app/studio/editor/polyline_edit.h"

#include <gtest/gtest.h>

namespace procex::studio {
namespace {

//  y
//  4 |     * 3 (2,4)
//  2 |  * 2 (1,2)        a profile: up, out, up
//  1 |  * 1 (1,1)
//  0 *  0 (0,0)
const std::vector<Vec2> kProfile = {{0, 0}, {1, 1}, {1, 2}, {2, 4}};

TEST(PolylineEdit, ProfilePointKeepsItsHeightBetweenItsNeighbours) {
  auto p = move_point(kProfile, 2, {3, 0.5}, kProfileRules);  // dragged below point 1
  EXPECT_EQ(p[2], (Vec2{3, 1}));
  p = move_point(kProfile, 2, {0.5, 9}, kProfileRules);  // above point 3
  EXPECT_EQ(p[2], (Vec2{0.5, 4}));
  p = move_point(kProfile, 3, {5, 10}, kProfileRules);  // the last point may rise freely
  EXPECT_EQ(p[3], (Vec2{5, 10}));
  for (std::size_t i = 1; i < p.size(); ++i) EXPECT_GE(p[i].y, p[i - 1].y);
}

TEST(PolylineEdit, ProfileStartIsPinned) {
  EXPECT_EQ(move_point(kProfile, 0, {3, 3}, kProfileRules), kProfile);
  auto r = remove_point(kProfile, 0, kProfileRules);
  ASSERT_FALSE(r);
  EXPECT_NE(r.message().find("(0, 0)"), std::string::npos);
}

TEST(PolylineEdit, PlanPointsMoveFreelyAndKeepThree) {
  const std::vector<Vec2> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_EQ(move_point(square, 0, {-5, -5}, kPlanRules)[0], (Vec2{-5, -5}));
  auto r = remove_point(square, 1, kPlanRules);
  ASSERT_TRUE(r);
  EXPECT_EQ(r.value().size(), 3u);
  EXPECT_FALSE(remove_point(r.value(), 0, kPlanRules));
}

TEST(PolylineEdit, InsertLandsOnTheEdgeIncludingTheClosingOne) {
  const std::vector<Vec2> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  auto p = insert_point(square, 3, {-1, 4}, kPlanRules);  // the closing edge (0,10)-(0,0)
  ASSERT_EQ(p.size(), 5u);
  EXPECT_EQ(p[4], (Vec2{0, 4}));
  // An open profile has no closing edge.
  EXPECT_EQ(insert_point(kProfile, 3, {1, 1}, kProfileRules).size(), kProfile.size());
  p = insert_point(kProfile, 2, {9, 3}, kProfileRules);  // projected onto (1,2)-(2,4)
  ASSERT_EQ(p.size(), 5u);
  for (std::size_t i = 1; i < p.size(); ++i) EXPECT_GE(p[i].y, p[i - 1].y);
}

TEST(PolylineEdit, HitTests) {
  const std::vector<Vec2> square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_EQ(nearest_point(square, {9.8, 0.1}, 0.5), 1u);
  EXPECT_FALSE(nearest_point(square, {5, 5}, 0.5));
  EXPECT_EQ(nearest_edge(square, {5, 0.2}, 0.5, true), 0u);
  EXPECT_EQ(nearest_edge(square, {0.2, 5}, 0.5, true), 3u);
  EXPECT_FALSE(nearest_edge(square, {0.2, 5}, 0.5, false));  // open: no closing edge
}

TEST(PolylineEdit, SnapsLevelOrPlumbWithANeighbourButNeverOntoIt) {
  // Point 2 dragged near the height of point 1: a horizontal run (a ledge).
  EXPECT_EQ(snap_to_neighbours(kProfile, 2, {1.6, 1.05}, 0.1, false), (Vec2{1.6, 1}));
  // Near point 3's offset: plumb below it.
  EXPECT_EQ(snap_to_neighbours(kProfile, 2, {1.95, 3}, 0.1, false), (Vec2{2, 3}));
  // Out of reach: unchanged.
  EXPECT_EQ(snap_to_neighbours(kProfile, 2, {1.5, 3}, 0.1, false), (Vec2{1.5, 3}));
  // Near both of point 1's coordinates: only the closer snap, so the points stay apart.
  EXPECT_EQ(snap_to_neighbours(kProfile, 2, {1.02, 1.05}, 0.1, false), (Vec2{1, 1.05}));
  // A closed loop's first point has the last one as a neighbour.
  const std::vector<Vec2> square = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  EXPECT_EQ(snap_to_neighbours(square, 0, {0.05, -1}, 0.1, true), (Vec2{0, -1}));
}

TEST(PolylineEdit, ProfileTagsStayOnePerSegment) {
  const std::vector<std::string> tags = {"wall", "soffit", "roof"};  // kProfile's three segments
  // A point inserted on the soffit: both halves are soffit.
  EXPECT_EQ(tags_after_insert(tags, 3, 1), (std::vector<std::string>{"wall", "soffit", "soffit", "roof"}));
  // Point 2 deleted: the soffit and the roof become one segment, the soffit's.
  EXPECT_EQ(tags_after_remove(tags, 3, 2), (std::vector<std::string>{"wall", "soffit"}));
  // The last point deleted: the last segment goes.
  EXPECT_EQ(tags_after_remove(tags, 3, 3), (std::vector<std::string>{"wall", "soffit"}));
  // Untagged profiles (or tags that do not match) are left alone.
  EXPECT_TRUE(tags_after_insert({}, 3, 1).empty());
  EXPECT_EQ(tags_after_remove({"a"}, 3, 1), (std::vector<std::string>{"a"}));
  const auto inserted = insert_point(kProfile, 1, {1, 1.5}, kProfileRules);
  EXPECT_EQ(tags_after_insert(tags, 3, 1).size(), inserted.size() - 1);
}

}  // namespace
}  // namespace procex::studio
