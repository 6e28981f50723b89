// The Profile Offset node through a real graph: its parameters, the override
// text, two nodes chained into two offsets, and errors for bad input.
#include <gtest/gtest.h>

#include "core/mesh/validate.h"
#include "graph/evaluator.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

using test::run_node;

//   3 +-----------+ 2      edges 0, 2 (12 m): "eaves"; edges 1, 3 (8 m): "gable"
//     |           |
//   0 +-----------+ 1
Footprint house() {
  Footprint fp = make_footprint({{{0, 0}, {12, 0}, {12, 8}, {0, 8}}}, 45.0);
  fp.profiles = {{"eaves", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}}, {"gable", {{0, 0}, {0, 30}}, {"gable"}}};
  for (EdgeSpec& e : fp.loops[0].edges) e.profile = e.id % 2 == 0 ? 0 : 1;
  return fp;
}

test::NodeRun offset(double height, double distance, const std::string& overrides, const Footprint& fp = house()) {
  return run_node("Profile Offset",
                  {{"height", Value::make(height)},
                   {"distance", Value::make(distance)},
                   {"overrides", Value::make(overrides)}},
                  {{"footprint", Value::make(fp)}});
}

const Profile& profile_of(const Footprint& fp, std::size_t edge) {
  return fp.profiles.at(static_cast<std::size_t>(fp.loops[0].edges.at(edge).profile));
}

TEST(ProfileOffsetNode, StepsEveryProfile) {
  const auto r = offset(3.0, 0.5, "");
  ASSERT_TRUE(r.ok()) << r.messages();
  const Footprint& fp = r.outputs.at(0).get<Footprint>();
  EXPECT_EQ(profile_of(fp, 0).points, (std::vector<glm::dvec2>{{0, 0}, {0, 3}, {0.5, 3}, {-4.5, 8}}));
  EXPECT_EQ(profile_of(fp, 1).points, (std::vector<glm::dvec2>{{0, 0}, {0, 3}, {0.5, 3}, {0.5, 30}}));
  EXPECT_EQ(profile_of(fp, 1).tags, (std::vector<std::string>{"gable", "soffit", "gable"}));
}

TEST(ProfileOffsetNode, OverridesByProfileAndEdge) {
  const auto r = offset(3.0, 0.5, "gable: drop;\n #2: distance=1.5, slope=60");
  ASSERT_TRUE(r.ok()) << r.messages();
  const Footprint& fp = r.outputs.at(0).get<Footprint>();
  EXPECT_EQ(profile_of(fp, 1).points, house().profiles[1].points);  // dropped: unchanged
  EXPECT_EQ(profile_of(fp, 0).points[2], glm::dvec2(0.5, 3));
  const Profile& own = profile_of(fp, 2);
  ASSERT_EQ(own.points.size(), 4u);
  EXPECT_EQ(own.points[2], glm::dvec2(1.5, 3));
  EXPECT_NEAR(own.angle_deg(2), 60.0, 1e-9);
}

// Two nodes in a chain, a plinth setback at 1 m and the eaves at 3 m with the
// gables dropped out, into Extrude: a valid solid with both steps.
TEST(ProfileOffsetNode, TwoChainedNodesMakeTwoOffsets) {
  Graph g;
  const NodeId plinth = *g.add_node("Profile Offset"), eaves = *g.add_node("Profile Offset");
  const NodeId extrude = *g.add_node("Extrude");
  EXPECT_TRUE(g.set_param(plinth, "height", Value::make(1.0)));
  EXPECT_TRUE(g.set_param(plinth, "distance", Value::make(-0.2)));
  EXPECT_TRUE(g.set_param(plinth, "tag", Value::make(std::string("plinth"))));
  EXPECT_TRUE(g.set_param(eaves, "overrides", Value::make(std::string("gable: drop"))));
  EXPECT_TRUE(g.add_input({"footprint", &value_type<Footprint>(), "", Value::make(house())}));
  EXPECT_TRUE(g.connect({kGraphInputs, 0}, {plinth, 0}));
  EXPECT_TRUE(g.connect(plinth, "footprint", eaves, "footprint"));
  EXPECT_TRUE(g.connect(eaves, "footprint", extrude, "footprint"));
  EXPECT_TRUE(g.add_output({"mesh", &value_type<MeshSet>(), ""}));
  EXPECT_TRUE(g.connect({extrude, 0}, {kGraphOutputs, 0}));
  ResultCache cache(16 << 20);
  Evaluator ev(cache, "profile offset test");
  const EvalResult r = ev.evaluate(g, {}, {"mesh"});
  std::string messages;
  for (const Diagnostic& d : r.diagnostics) messages += d.to_string() + "\n";
  ASSERT_TRUE(r.ok()) << messages;
  const TaggedMesh& part = r.output("mesh")->get<MeshSet>().parts.at(0);
  const ValidationReport v = validate(*part.mesh);
  EXPECT_TRUE(v.ok());
  // 12 x 8 to 1 m, 11.6 x 7.6 to 3 m, then a 45 degree gable roof 8.6 m wide
  // over the 11.6 m between the gables.
  EXPECT_NEAR(v.volume, 12 * 8 + 11.6 * 7.6 * 2 + 11.6 * 8.6 * 8.6 / 4, 1e-6);
  std::map<std::string, int> tags;
  for (std::size_t f = 0; f < part.face_tags.size(); ++f) ++tags[face_tag(part, f)];
  EXPECT_EQ(tags.at("plinth"), 4);
  EXPECT_EQ(tags.at("soffit"), 2);
}

TEST(ProfileOffsetNode, BadInputIsAnErrorNamingIt) {
  const std::pair<const char*, const char*> cases[] = {
      {"gable drop", "rule 1 ('gable drop') has no ':'"},
      {"gable: drop; #x: drop", "rule 2 ('#x: drop') '#x' is not an edge id"},
      {"gable: lift=2", "unknown setting 'lift=2'"},
      {"gable: slope=steep", "slope 'steep' is not a number"},
      {"mansard: drop", "no profile named 'mansard'"},
      {"#9: distance=1", "no edge with id 9"},
      {": drop", "names no profile and no edge"},
  };
  for (const auto& [text, words] : cases) {
    const auto r = offset(3.0, 0.5, text);
    EXPECT_FALSE(r.ok()) << text;
    EXPECT_NE(r.messages().find(words), std::string::npos) << text << ": " << r.messages();
  }
  const auto low = offset(0.0, 0.5, "");
  EXPECT_FALSE(low.ok());
  EXPECT_NE(low.messages().find("profile offset 'at 0 m': height 0.000000 must be above 0"), std::string::npos)
      << low.messages();
}

}  // namespace
}  // namespace procex
