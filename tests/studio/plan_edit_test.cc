// The plan editor's hole editing: core's footprint checks named by loop and
// vertex, new holes placed inside any outer loop and clear of the others, and
// the edits on a Footprint Polygon's holes going through the undo stack.
#include "app/studio/editor/plan_edit.h"

#include <gtest/gtest.h>

#include <chrono>

#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"
#include "core/geom/footprint.h"
#include "graph/pxg.h"
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
  EXPECT_FALSE(check_plan(kOuter, {kHole}));
}

TEST(PlanEdit, AHoleVertexDraggedThroughTheOuterLoopIsNamed) {
  const std::vector<Vec2> hole = move_point(kHole, 2, {12, 6}, kPlanRules);
  const auto issue = check_plan(kOuter, {hole});
  ASSERT_TRUE(issue);
  EXPECT_NE(issue->message.find("cross"), std::string::npos) << issue->message;
  EXPECT_GE(issue->loop, 0);
  EXPECT_GE(issue->vertex, 0);
}

TEST(PlanEdit, ASelfIntersectingHoleNamesTheHoleAndAVertex) {
  //  a bow tie: corners 1 and 2 swapped, as the second hole
  const std::vector<Vec2> bow = {{5, 3}, {6, 4}, {5, 4}, {6, 3}};
  const auto issue = check_plan(kOuter, {{{1, 1}, {1, 2}, {2, 2}, {2, 1}}, bow});
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->loop, 2);
  EXPECT_GE(issue->vertex, 0);
  EXPECT_EQ(issue->message.rfind("hole 2, vertex " + std::to_string(issue->vertex) + ":", 0), 0u) << issue->message;
  EXPECT_NE(issue->message.find("intersects itself"), std::string::npos) << issue->message;
}

TEST(PlanEdit, AHoleOutsideTheOuterLoopIsRefused) {
  const std::vector<Vec2> away = {{13, 2}, {13, 6}, {17, 6}, {17, 2}};
  const auto issue = check_plan(kOuter, {away});
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->loop, 1);
  EXPECT_NE(issue->message.find("outside the outer loop"), std::string::npos) << issue->message;
}

TEST(PlanEdit, AHoleInsideAnotherHoleIsRefused) {
  const std::vector<Vec2> inner = {{4, 3}, {4, 5}, {6, 5}, {6, 3}};
  const auto issue = check_plan(kOuter, {kHole, inner});
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->loop, 2);
  EXPECT_EQ(issue->message.rfind("hole 2: lies inside hole 1", 0), 0u) << issue->message;
}

TEST(PlanEdit, ATooSmallHoleIsNamed) {
  const auto issue = check_plan(kOuter, {{{3, 2}, {3, 6}}});
  ASSERT_TRUE(issue);
  EXPECT_EQ(issue->loop, 1);
  EXPECT_EQ(issue->message.rfind("hole 1", 0), 0u) << issue->message;
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
    EXPECT_FALSE(check_plan(outer, {hole})) << check_plan(outer, {hole})->message;
  }
  EXPECT_TRUE(hole_inside({{0, 0}, {1, 0}}).empty());
}

TEST(PlanEdit, MoreHolesFitBesideTheOthers) {
  const std::vector<Vec2> wide = {{0, 0}, {30, 0}, {30, 10}, {0, 10}};
  PlanLoops holes;
  for (int i = 0; i < 3; ++i) {
    holes.push_back(hole_inside(wide, holes));
    ASSERT_EQ(holes.back().size(), 4u) << "hole " << i + 1;
    EXPECT_FALSE(check_plan(wide, holes)) << check_plan(wide, holes)->message;
  }
}

TEST(PlanEdit, HoleEditsAreUndoSteps) {
  Document doc;
  const NodeId id = *doc.add_node("Footprint Polygon", 0, 0);
  const std::size_t points = *doc.graph().node(id)->decl().param_index("points");
  const std::size_t holes = *doc.graph().node(id)->decl().param_index("holes");
  auto holes_now = [&] { return doc.graph().node(id)->params[holes].get<PlanLoops>(); };
  auto set_hole = [&](std::size_t k, std::vector<Vec2> v) {
    PlanLoops next = holes_now();
    next[k] = std::move(v);
    return doc.set_param(id, holes, Value::make(std::move(next)));
  };
  ASSERT_TRUE(doc.set_param(id, points, Value::make(std::vector<Vec2>{{0, 0}, {20, 0}, {20, 8}, {0, 8}})));
  const auto outer = doc.graph().node(id)->params[points].get<std::vector<Vec2>>();
  ASSERT_TRUE(holes_now().empty());
  const PlanLoops one = {hole_inside(outer)};
  ASSERT_TRUE(doc.set_param(id, holes, Value::make(one)));                                       // add a hole
  const PlanLoops two = {one[0], hole_inside(outer, one)};
  ASSERT_TRUE(doc.set_param(id, holes, Value::make(two)));                                       // and a second
  const Vec2 mid{(two[1][0].x + two[1][1].x) / 2, (two[1][0].y + two[1][1].y) / 2};
  ASSERT_TRUE(set_hole(1, insert_point(holes_now()[1], 0, mid, kPlanRules)));                    // insert a vertex in the second
  ASSERT_EQ(holes_now()[1].size(), 5u);
  ASSERT_TRUE(set_hole(1, remove_point(holes_now()[1], 1, kPlanRules).value()));                  // delete it again
  EXPECT_FALSE(check_plan(outer, holes_now())) << check_plan(outer, holes_now())->message;
  ASSERT_TRUE(doc.set_param(id, holes, Value::make(PlanLoops{two[1]})));                          // delete the first hole
  EXPECT_FALSE(check_plan(outer, holes_now())) << check_plan(outer, holes_now())->message;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(doc.undo());
  EXPECT_EQ(holes_now(), two);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(holes_now(), one);
  ASSERT_TRUE(doc.undo());
  EXPECT_TRUE(holes_now().empty());
}

// Footprint Polygon version 1 had one `hole`: older files load with it as the only one of `holes`.
TEST(PlanEdit, AVersion1HoleBecomesTheFirstOfTheHoles) {
  const auto recipe = [](const std::string& hole) {
    return R"({"format": "procex-graph", "version": 2, "inputs": [], "outputs": [], "links": [], "nodes": [
      {"id": 1, "type": "Footprint Polygon", "version": 1,
       "params": {"points": [[0, 0], [10, 0], [10, 8], [0, 8]], "hole": )" + hole + "}}]}";
  };
  const Graph g = parse_pxg(recipe("[[3, 2], [3, 6], [7, 6], [7, 2]]"), "old.pxg");
  const Node* n = g.node(1);
  EXPECT_EQ(n->type->version(), 2);
  EXPECT_EQ(n->params[*n->decl().param_index("holes")].get<PlanLoops>(), PlanLoops{kHole});
  EXPECT_NE(to_pxg(g).find("\"holes\": [\n"), std::string::npos) << "saved as holes";
  EvalWorker worker;
  worker.submit(1, g, {PortRef{1, 0}});
  ASSERT_TRUE(worker.wait_idle(std::chrono::seconds(60)));
  const auto snap = worker.latest();
  ASSERT_TRUE(snap && snap->values.count(PortRef{1, 0}));
  EXPECT_EQ(snap->values.at(PortRef{1, 0}).get<Footprint>().loops.size(), 2u);

  const Graph none = parse_pxg(recipe("[]"), "old.pxg");
  EXPECT_TRUE(none.node(1)->params[1].get<PlanLoops>().empty());
  try {
    (void)parse_pxg(recipe("3"), "old.pxg");
    ADD_FAILURE() << "a hole that is not a list of corners loads";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/nodes/0/params/holes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace procex::studio
