// samples/chimney.pxg: a chimney stack placed upright at an anchor on a roof
// slope stands vertical, is sunk into the roof below it and rises above the
// ridge; moving the anchor along the edge moves it along the eave.
#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

const std::filesystem::path kSamples = PROCEX_SAMPLES;

Instance chimney(Graph& g) {
  const EvalResult r = test::evaluate_mesh(g, kSamples);
  EXPECT_TRUE(r.ok());
  const auto& placed = r.output("mesh")->get<MeshSet>().parts.at(0).placed;
  EXPECT_EQ(placed.instances.size(), 1u);
  return placed.instances.at(0);
}

TEST(ChimneySample, StandsUprightThroughTheRoof) {
  Graph g = load_pxg(kSamples / "chimney.pxg");
  const Instance c = chimney(g);
  // The mesh's y (its height) is the world's z, scaled to 3.5 m; x runs along the eave.
  EXPECT_NEAR(c.transform[1][2], 3.5, 1e-9);
  EXPECT_NEAR(c.transform[1][0], 0.0, 1e-9);
  EXPECT_NEAR(c.transform[1][1], 0.0, 1e-9);
  EXPECT_NEAR(c.transform[0][0], 1.0, 1e-9);
  // Its foot, 1 m below the anchor at 5.5 m on the 45 degree slope, is under
  // the roof; its top (8 m) above the 7.5 m ridge of the 12 x 9 hip roof.
  const glm::dvec4 foot = c.transform * glm::dvec4(0.4, 0, 0.4, 1);
  const glm::dvec4 top = c.transform * glm::dvec4(0.4, 1, 0.4, 1);
  EXPECT_NEAR(foot.z, 4.5, 1e-9);
  EXPECT_NEAR(top.z, 8.0, 1e-9);
  // The front slope rises 1 m per metre in from y = -4.5: under the foot the roof is higher.
  EXPECT_LT(foot.z, 3.0 + (foot.y + 4.5));
}

TEST(ChimneySample, FollowsItsAnchorAlongTheEave) {
  Graph g = load_pxg(kSamples / "chimney.pxg");
  const double x = chimney(g).transform[3][0];
  ASSERT_TRUE(g.set_exposed("position", Value::make(0.3)));
  EXPECT_LT(chimney(g).transform[3][0], x - 1.0);
}

}  // namespace
}  // namespace procex
