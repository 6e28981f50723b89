// The Anchor node and Extrude's anchor inputs: parameters become an
// AnchorSpec, malformed ones are refused by parameter name, Extrude resolves
// the spec's profile name on its footprint and carries the sweep's
// resolutions on its mesh, absent ones as warnings.
#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

using test::run_node;

TEST(AnchorNode, ParametersBecomeTheSpec) {
  const auto r = run_node("Anchor", {{"name", Value::make(std::string("sill"))},
                                     {"mode", Value::make(EnumValue{"from_end"})},
                                     {"position", Value::make(1.5)},
                                     {"height", Value::make(4.0)},
                                     {"profile", Value::make(std::string("wall"))},
                                     {"edges", Value::make(std::string(" 0, 2,5 "))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const AnchorSpec& s = r.outputs.at(0).get<AnchorSpec>();
  EXPECT_EQ(s.anchor.name, "sill");
  EXPECT_EQ(s.anchor.plan.mode, PlanAnchor::Mode::FromEnd);
  EXPECT_EQ(s.anchor.plan.value, 1.5);
  EXPECT_EQ(s.anchor.height, 4.0);
  EXPECT_EQ(s.anchor.profile, -1);  // Extrude resolves the name
  EXPECT_EQ(s.profile, "wall");
  EXPECT_EQ(s.anchor.edges, (std::vector<std::int32_t>{0, 2, 5}));
}

TEST(AnchorNode, RefusesMalformedEdgesNamingTheParameter) {
  for (const char* text : {"1,,2", "1, x", "1.5", "-1", "2,", "99999999999"}) {
    const auto r = run_node("Anchor", {{"edges", Value::make(std::string(text))}});
    EXPECT_FALSE(r.ok()) << text;
    EXPECT_NE(r.messages().find("edges: item"), std::string::npos) << r.messages();
  }
}

TEST(AnchorNode, RefusesAFractionAboveOneAndAnEmptyName) {
  auto r = run_node("Anchor", {{"position", Value::make(2.0)}});
  EXPECT_NE(r.messages().find("position: 2.0"), std::string::npos) << r.messages();
  r = run_node("Anchor", {{"name", Value::make(std::string())}});
  EXPECT_NE(r.messages().find("name:"), std::string::npos) << r.messages();
}

// A 10 x 6 block: walls of profile "wall" (vertical, 6 m) on edges 0 and 2,
// the others "end" (vertical, 3 m).
//
//   (0,6) +----2----+ (10,6)
//         3         1
//   (0,0) +----0----+ (10,0)
Footprint block() {
  Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 6}, {0, 6}}}, 0);
  fp.profiles = {{"wall", {{0, 0}, {0, 6}}, {"wall"}}, {"end", {{0, 0}, {0, 3}}, {"wall"}}};
  for (EdgeSpec& e : fp.loops[0].edges) e.profile = e.id % 2 == 0 ? 0 : 1;
  return fp;
}

struct AnchoredExtrude {
  Graph g;
  NodeId anchor = 0, extrude = 0;
  ResultCache cache{64 << 20};
  Evaluator ev{cache, "anchor test"};

  AnchoredExtrude() {
    anchor = *g.add_node("Anchor");
    extrude = *g.add_node("Extrude");
    EXPECT_TRUE(g.set_param(extrude, "anchors", Value::make<std::int64_t>(1)));
    EXPECT_TRUE(g.add_input({"footprint", &value_type<Footprint>(), "", Value::make(block())}));
    EXPECT_TRUE(g.connect({kGraphInputs, 0}, {extrude, 0}));
    EXPECT_TRUE(g.connect(anchor, "anchor", extrude, "anchor_1"));
    EXPECT_TRUE(g.add_output({"mesh", &value_type<MeshSet>(), ""}));
    EXPECT_TRUE(g.connect({extrude, 0}, {kGraphOutputs, 0}));
  }
  void set(const std::string& param, Value v) { EXPECT_TRUE(g.set_param(anchor, param, std::move(v))); }
  EvalResult run() { return ev.evaluate(g, {}, {"mesh"}); }
};

std::string messages(const EvalResult& r) {
  std::string out;
  for (const Diagnostic& d : r.diagnostics) out += d.to_string() + "\n";
  return out;
}

TEST(ExtrudeAnchors, ResolvesOnTheEdgesOfTheNamedProfile) {
  AnchoredExtrude t;
  t.set("profile", Value::make(std::string("wall")));
  t.set("height", Value::make(2.0));
  t.set("position", Value::make(0.25));
  const EvalResult r = t.run();
  ASSERT_TRUE(r.ok()) << messages(r);
  const TaggedMesh& part = r.output("mesh")->get<MeshSet>().parts.at(0);
  ASSERT_EQ(part.anchors.size(), 2u);
  const ResolvedAnchor &front = part.anchors[0], &back = part.anchors[1];
  EXPECT_EQ(front.edge_id, 0);
  EXPECT_EQ(back.edge_id, 2);
  ASSERT_TRUE(front.present && back.present);
  EXPECT_NEAR(glm::distance(front.frame.origin, glm::dvec3(2.5, 0, 2)), 0, 1e-9);
  EXPECT_NEAR(glm::distance(back.frame.origin, glm::dvec3(7.5, 6, 2)), 0, 1e-9);
  EXPECT_NEAR(glm::distance(front.frame.normal, glm::dvec3(0, -1, 0)), 0, 1e-9);
}

TEST(ExtrudeAnchors, AbsentAboveTheTopIsAWarningNotAnError) {
  AnchoredExtrude t;
  t.set("height", Value::make(7.0));  // the sweep caps at the highest profile top, 6 m
  const EvalResult r = t.run();
  ASSERT_TRUE(r.ok()) << messages(r);
  const TaggedMesh& part = r.output("mesh")->get<MeshSet>().parts.at(0);
  ASSERT_EQ(part.anchors.size(), 4u);
  std::size_t warnings = 0;
  for (const ResolvedAnchor& a : part.anchors) EXPECT_FALSE(a.present);
  for (const Diagnostic& d : r.diagnostics)
    if (d.severity == Severity::kWarning && d.message.find("anchor 'window' is absent on edge") != std::string::npos)
      ++warnings;
  EXPECT_EQ(warnings, 4u) << messages(r);
}

TEST(ExtrudeAnchors, UnknownProfileNameListsTheFootprintsProfiles) {
  AnchoredExtrude t;
  t.set("profile", Value::make(std::string("gable")));
  const EvalResult r = t.run();
  EXPECT_FALSE(r.ok());
  EXPECT_NE(messages(r).find("anchor 'window': the footprint has no profile named 'gable' (its profiles: 'wall', 'end')"),
            std::string::npos)
      << messages(r);
}

TEST(ExtrudeAnchors, ResolvesOnTheListedEdgesOnly) {
  AnchoredExtrude t;
  t.set("edges", Value::make(std::string("3, 1")));
  t.set("mode", Value::make(EnumValue{"from_start"}));
  t.set("position", Value::make(1.0));
  const EvalResult r = t.run();
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& anchors = r.output("mesh")->get<MeshSet>().parts.at(0).anchors;
  ASSERT_EQ(anchors.size(), 2u);
  EXPECT_EQ(anchors[0].edge_id, 1);  // in the footprint's order
  EXPECT_EQ(anchors[1].edge_id, 3);
  EXPECT_NEAR(glm::distance(anchors[0].frame.origin, glm::dvec3(10, 1, 1)), 0, 1e-9);  // 1 m from (10, 0)
  EXPECT_NEAR(glm::distance(anchors[1].frame.origin, glm::dvec3(0, 5, 1)), 0, 1e-9);   // 1 m from (0, 6)
}

TEST(ExtrudeAnchors, UnknownEdgeIdListsTheFootprintsIds) {
  AnchoredExtrude t;
  t.set("edges", Value::make(std::string("1, 7")));
  const EvalResult r = t.run();
  EXPECT_FALSE(r.ok());
  EXPECT_NE(messages(r).find("edge id 7 is not an edge of the footprint (its ids: 0-3)"), std::string::npos)
      << messages(r);
}

// A batch draws profiles per building: an anchor for a profile no edge of
// this footprint uses is absent there, not an error.
TEST(ExtrudeAnchors, AProfileNoEdgeUsesIsAbsentWithAWarning) {
  AnchoredExtrude t;
  t.set("profile", Value::make(std::string("end")));
  t.set("edges", Value::make(std::string("0")));  // a "wall" edge
  const EvalResult r = t.run();
  ASSERT_TRUE(r.ok()) << messages(r);
  const auto& anchors = r.output("mesh")->get<MeshSet>().parts.at(0).anchors;
  ASSERT_EQ(anchors.size(), 1u);
  EXPECT_FALSE(anchors[0].present);
  EXPECT_EQ(anchors[0].edge_id, -1);
  EXPECT_NE(messages(r).find("anchor 'window' is absent: no edge it lists uses profile 'end' on this footprint"),
            std::string::npos)
      << messages(r);
}

// The cache key covers the anchor: changing it runs Extrude again, an
// unchanged graph is served from the cache.
TEST(ExtrudeAnchors, ChangingTheAnchorReevaluatesExtrude) {
  AnchoredExtrude t;
  const EvalResult first = t.run();
  ASSERT_TRUE(first.ok()) << messages(first);
  const EvalResult again = t.run();
  EXPECT_EQ(again.stats.computed(), 0u);
  t.set("height", Value::make(2.5));
  const EvalResult moved = t.run();
  ASSERT_TRUE(moved.ok()) << messages(moved);
  EXPECT_EQ(moved.stats.find(NodePath{t.extrude})->outcome, NodeOutcome::kComputed);
  EXPECT_NE(moved.output("mesh")->content_hash(), first.output("mesh")->content_hash());
  EXPECT_NEAR(moved.output("mesh")->get<MeshSet>().parts[0].anchors[0].frame.origin.z, 2.5, 1e-9);
}

}  // namespace
}  // namespace procex
