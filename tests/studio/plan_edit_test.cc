// The plan editor's hole editing: core's footprint checks named by loop and
// vertex, a first hole placed inside any outer loop, and the edits on a
// Footprint Polygon going through the undo stack.
#include "app/studio/editor/plan_edit.h"

#include <gtest/gtest.h>

#include "app/studio/editor/document.h"
#include "app/studio/editor/polyline_edit.h"
#include "core/geom/nesting.h"

namespace procex::studio {
namespace {

//  8 +-----------+
//    |  +-----+  |      a 10 x 8 outer loop (counter-clockwise)
//    |  | hole|  |      and a clockwise 4 x 4 hole
//    |  +-----+  |
//  0 +-----------+
//    0           10
const std::vector<Vec2> kOuter = {{0, 0}, {10, 0}, {10, 8}, {0, 8}};
const std::vector<Vec2> kHole = {{3, 2}, {3, 6}, {7, 6}, {7, 2}};

double signed_area(const std::vector<Vec2>& pts) {
  std::vector<glm::dvec2> loop;
  for (const Vec2& p : pts) loop.push_back({p.x, p.y});
  return 0.5 * twice_signed_area(loop);
}

TEST(PlanEdit, ACourtyardPlanIsAccepted) {
  EXPECT_FALSE(check_plan(kOuter, {}));
  EXPECT_FALSE(check_plan(kOuter, kHole));
}

TEST(PlanEdit, AHoleVertexDraggedThroughTheOuterLoopIsNamed) {
  const std::vector<Vec2> hole = move_point(kHole, 2, {12, 6}, kPlanRules);
  const auto issue = check_plan(kOuter, hole);
  ASSERT_TRUE(issue);
  EXPECT_NE(issue->message.find("cross"), std::string::npos) << issue->message;
  EXPECT_GE(issue->loop, 0);
  EXPECT_GE(issue->vertex, 0);
}

TEST(PlanEdit, ASelfIntersectingHoleNamesTheHoleAndAVertex) {
  //  a bow tie: corners 1 and 2 swapped
  const std::vector<Vec2> bow = {{3, 2}, {7, 6}, {3, 6}, {7, 2}};
  const auto issue = check_plan(kOuter, bow);
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->loop, 1);
  EXPECT_GE(issue->vertex, 0);
  EXPECT_EQ(issue->message.rfind("hole, vertex " + std::to_string(issue->vertex) + ":", 0), 0u) << issue->message;
  EXPECT_NE(issue->message.find("intersects itself"), std::string::npos) << issue->message;
}

TEST(PlanEdit, AHoleOutsideTheOuterLoopIsRefused) {
  const std::vector<Vec2> away = {{13, 2}, {13, 6}, {17, 6}, {17, 2}};
  const auto issue = check_plan(kOuter, away);
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->loop, 1);
  EXPECT_NE(issue->message.find("outside the outer loop"), std::string::npos) << issue->message;
}

TEST(PlanEdit, ATooSmallHoleIsNamed) {
  const auto issue = check_plan(kOuter, {{3, 2}, {3, 6}});
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->loop, 1);
  EXPECT_EQ(issue->message.rfind("hole", 0), 0u) << issue->message;
}

TEST(PlanEdit, ANewHoleFitsInsideRectanglesAndLShapes) {
  //  +--+
  //  |  |        an L: the bounding box's centre (5, 5) is outside it,
  //  |  +-----+  so the hole must find the inside elsewhere
  //  +--------+
  const std::vector<Vec2> l = {{0, 0}, {10, 0}, {10, 3}, {3, 3}, {3, 10}, {0, 10}};
  for (const auto& outer : {kOuter, l}) {
    const std::vector<Vec2> hole = hole_inside(outer);
    ASSERT_EQ(hole.size(), 4u);
    EXPECT_LT(signed_area(hole), 0.0);  // clockwise, as holes run
    EXPECT_FALSE(check_plan(outer, hole)) << check_plan(outer, hole)->message;
  }
  EXPECT_TRUE(hole_inside({{0, 0}, {1, 0}}).empty());
}

TEST(PlanEdit, HoleEditsAreUndoSteps) {
  Document doc;
  const NodeId id = *doc.add_node("Footprint Polygon", 0, 0);
  const std::size_t points = *doc.graph().node(id)->decl().param_index("points");
  const std::size_t hole = *doc.graph().node(id)->decl().param_index("hole");
  auto hole_now = [&] { return doc.graph().node(id)->params[hole].get<std::vector<Vec2>>(); };
  const auto outer = doc.graph().node(id)->params[points].get<std::vector<Vec2>>();
  ASSERT_TRUE(hole_now().empty());
  const std::vector<Vec2> added = hole_inside(outer);
  ASSERT_TRUE(doc.set_param(id, hole, Value::make(added)));                                                  // add the hole
  ASSERT_TRUE(doc.set_param(id, hole, Value::make(insert_point(hole_now(), 1, {5, 5}, kPlanRules))));      // insert a vertex
  ASSERT_EQ(hole_now().size(), 5u);
  ASSERT_TRUE(doc.set_param(id, hole, Value::make(move_point(hole_now(), 0, {4, 3}, kPlanRules))));       // move one
  ASSERT_TRUE(doc.set_param(id, hole, Value::make(remove_point(hole_now(), 2, kPlanRules).value())));    // delete one
  EXPECT_EQ(hole_now().size(), 4u);
  EXPECT_FALSE(check_plan(outer, hole_now())) << check_plan(outer, hole_now())->message;
  ASSERT_TRUE(doc.set_param(id, hole, Value::make(std::vector<Vec2>{})));                                  // delete the hole
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(doc.undo());
  EXPECT_EQ(hole_now(), added);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(hole_now().empty());
}

}  // namespace
}  // namespace procex::studio
