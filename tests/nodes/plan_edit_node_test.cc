// The Plan Edit node and Extrude's plan edit inputs: parameters become a
// PlanEditSpec (copies side by side, shapes parsed with errors naming the
// point), Extrude places the edits at their anchors with their own profiles,
// edits that do not fit become warnings, and growing Extrude's anchor inputs
// keeps the plan edit links (the second variadic group moves).
#include <algorithm>

#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/support/mesh_summary.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

using test::run_node;

AnchorSpec anchor_on(std::int32_t edge, double height) {
  AnchorSpec a;
  a.anchor.name = "bay";
  a.anchor.height = height;
  a.anchor.edges = {edge};
  return a;
}

TEST(PlanEditNode, CopiesSitSideBySideCentredOnTheAnchor) {
  const auto r = run_node("Plan Edit", {{"count", Value::make<std::int64_t>(3)}, {"spacing", Value::make(5.0)}},
                          {{"at", Value::make(anchor_on(0, 3.0))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const PlanEditSpec& s = r.outputs.at(0).get<PlanEditSpec>();
  ASSERT_EQ(s.edits.size(), 3u);
  EXPECT_EQ(s.edits[0].offset, -5.0);
  EXPECT_EQ(s.edits[1].offset, 0.0);
  EXPECT_EQ(s.edits[2].offset, 5.0);
  EXPECT_EQ(s.edits[0].kind, PlanEdit::Kind::Natural);
  EXPECT_EQ(s.edits[0].edges.size(), 3u);
  EXPECT_EQ(s.edits[0].name, "bay");
  EXPECT_TRUE(s.profiles.empty());
}

TEST(PlanEditNode, ForcedShapesAreParsedAndBadPointsNamed) {
  auto r = run_node("Plan Edit", {{"kind", Value::make(EnumValue{"forced"})},
                                  {"shape", Value::make(std::string("-1 0; -1 0.5; 0 1; 1 0.5; 1 0"))}},
                    {{"at", Value::make(anchor_on(0, 0.0))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const PlanEditSpec& s = r.outputs.at(0).get<PlanEditSpec>();
  EXPECT_EQ(s.edits.at(0).shape.size(), 5u);
  EXPECT_EQ(s.edits.at(0).edges.size(), 4u);
  EXPECT_EQ(s.edits.at(0).shape[2], glm::dvec2(0, 1));
  for (const char* text : {"-1 0; x 1; 1 0", "-1 0; 1; 1 0", "-1 0; 1 1 1; 1 0"}) {
    r = run_node("Plan Edit", {{"kind", Value::make(EnumValue{"forced"})}, {"shape", Value::make(std::string(text))}},
                 {{"at", Value::make(anchor_on(0, 0.0))}});
    EXPECT_FALSE(r.ok()) << text;
    EXPECT_NE(r.messages().find("shape: point 2"), std::string::npos) << r.messages();
  }
}

// A 12 x 8 box of vertical walls, 6 m high.
Footprint block() {
  Footprint fp = make_footprint({{{0, 0}, {12, 0}, {12, 8}, {0, 8}}}, 0);
  fp.profiles = {{"wall", {{0, 0}, {0, 6}}, {"wall"}}};
  for (EdgeSpec& e : fp.loops[0].edges) e.profile = 0;
  return fp;
}

PlanEditSpec bay(double width) {
  PlanEditSpec s;
  s.at = anchor_on(0, 2.0);
  PlanEdit e;
  e.name = "bay";
  e.kind = PlanEdit::Kind::Natural;
  e.width = width;
  e.depth = 1.0;
  e.edges.assign(3, EdgeSpec{0.0, -1, 0});
  s.edits = {e};
  s.profiles = {{"bay", {{0, 0}, {0, 3}}, {"bay wall"}}};
  return s;
}

TEST(PlanEditNode, ExtrudeInsertsTheStepWithItsOwnProfile) {
  const auto r = run_node("Extrude", {{"plan_edits", Value::make<std::int64_t>(1)}, {"validate", Value::make(true)}},
                          {{"footprint", Value::make(block())}, {"edit_1", Value::make(bay(4.0))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const MeshSummary s = summarize(r.outputs.at(0).get<MeshSet>());
  // A 4 x 1 bay from 2 m on a 12 x 8 x 6 block: its profile's top is 5 m, but
  // like any profile's last segment its walls carry on up to the block's top.
  EXPECT_NEAR(s.volume, 12 * 8 * 6 + 4 * 1 * 4, 1e-6);
  EXPECT_EQ(s.faces_per_tag.at("bay wall"), 3);
  EXPECT_EQ(s.faces_per_tag.at("step"), 1);
}

TEST(PlanEditNode, AStepThatDoesNotFitIsAWarning) {
  const auto r = run_node("Extrude", {{"plan_edits", Value::make<std::int64_t>(1)}},
                          {{"footprint", Value::make(block())}, {"edit_1", Value::make(bay(20.0))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_NE(r.messages().find("plan edit 'bay' is not applied on edge 0: it does not fit"), std::string::npos)
      << r.messages();
  EXPECT_NEAR(summarize(r.outputs.at(0).get<MeshSet>()).volume, 12 * 8 * 6, 1e-6);
}

TEST(PlanEditNode, AnUnknownAnchorProfileIsAnError) {
  PlanEditSpec s = bay(4.0);
  s.at.profile = "roof";
  const auto r = run_node("Extrude", {{"plan_edits", Value::make<std::int64_t>(1)}},
                          {{"footprint", Value::make(block())}, {"edit_1", Value::make(s)}});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.messages().find("plan edit 'bay': the footprint has no profile named 'roof'"), std::string::npos)
      << r.messages();
}

TEST(PlanEditNode, MoreAnchorInputsKeepThePlanEditLinks) {
  Graph g = load_pxg(std::filesystem::path(PROCEX_SAMPLES) / "plan_edits.pxg");
  auto source_of = [&](const char* input) {
    const auto& inputs = g.node(5)->decl().inputs();
    const auto it = std::find_if(inputs.begin(), inputs.end(), [&](const PortDecl& p) { return p.name == input; });
    EXPECT_NE(it, inputs.end()) << input;
    return g.source({5, static_cast<std::uint32_t>(it - inputs.begin())});
  };
  const auto before = source_of("edit_2");
  ASSERT_TRUE(before.has_value());
  ASSERT_TRUE(g.set_param(5, "anchors", Value::make<std::int64_t>(2)));
  EXPECT_EQ(source_of("edit_2"), before);
  EXPECT_FALSE(source_of("anchor_1").has_value());
  const EvalResult r = test::evaluate_mesh(g, PROCEX_SAMPLES);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(summarize(r.output("mesh")->get<MeshSet>()).faces_per_tag.at("recess wall"), 3);
}

}  // namespace
}  // namespace procex
