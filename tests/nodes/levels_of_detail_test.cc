// One recipe at every level of detail (EvalOptions::lod, the graph input
// `lod`): samples/setback_tower.pxg, whose windows are placed in a facade split
// and cut into the walls. The levels nest: LOD3 is today's output, LOD2 the
// same buildings unplaced and uncut, LOD1 a block holding LOD2's volume at its
// mean height, LOD0 the footprint.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/validate.h"
#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "nodes/values.h"
#include "tests/support/plan_of_mesh.h"

namespace procex {
namespace {

const std::filesystem::path kSamples = PROCEX_SAMPLES;

struct Level {
  EvalResult result;
  const MeshSet& meshes() const { return result.output("mesh")->get<MeshSet>(); }
};

class LevelsOfDetail : public ::testing::Test {
 protected:
  Level at(std::optional<int> lod, const Bindings& bindings = {}) {
    EvalOptions options;
    options.folder = kSamples;
    options.lod = lod;
    Level l{evaluator_.evaluate(graph_, bindings, {"mesh"}, options)};
    if (!lod || *lod <= kFullDetail) {
      EXPECT_TRUE(l.result.ok()) << (l.result.diagnostics.empty() ? "" : l.result.diagnostics[0].to_string());
    }
    return l;
  }
  Graph graph_ = load_pxg(kSamples / "setback_tower.pxg");
  ResultCache cache_{256 << 20};
  Evaluator evaluator_{cache_, "levels of detail test"};
};
using test::plan_of;
using test::Plan;

std::size_t placed(const MeshSet& s) {
  std::size_t n = 0;
  for (const TaggedMesh& p : s.parts) n += p.placed.instances.size();
  return n;
}

TEST_F(LevelsOfDetail, FullDetailIsTodaysOutput) {
  const Level today = at(std::nullopt), full = at(kFullDetail);
  EXPECT_EQ(today.result.outputs[0].hash, full.result.outputs[0].hash);
  EXPECT_EQ(full.result.lod, kFullDetail);
  EXPECT_GT(placed(full.meshes()), 0u);
}

TEST_F(LevelsOfDetail, TheRoofShapesHaveNoPlacedMeshesAndNoCuts) {
  const Level full = at(kFullDetail), shape = at(2);
  ASSERT_EQ(shape.meshes().parts.size(), full.meshes().parts.size());
  EXPECT_EQ(placed(shape.meshes()), 0u);
  for (const NodeStats& n : shape.result.stats.nodes) EXPECT_NE(n.type, "Mesh Placement") << "ran at LOD2";
  for (std::size_t i = 0; i < full.meshes().parts.size(); ++i) {
    const ValidationReport v2 = validate(*shape.meshes().parts[i].mesh);
    EXPECT_TRUE(v2.ok()) << ::testing::PrintToString(v2.problems);
    // The windows' openings are cut out of LOD3's walls only.
    EXPECT_GT(v2.volume, validate(*full.meshes().parts[i].mesh).volume);
    EXPECT_LT(shape.meshes().parts[i].mesh->n_faces(), full.meshes().parts[i].mesh->n_faces());
  }
}

TEST_F(LevelsOfDetail, TheBlockHoldsTheShapesVolumeAtItsMeanHeight) {
  const Level shape = at(2), block = at(1), footprint = at(0);
  ASSERT_EQ(shape.meshes().parts.size(), 1u);
  ASSERT_EQ(block.meshes().parts.size(), shape.meshes().parts.size());
  ASSERT_EQ(footprint.meshes().parts.size(), shape.meshes().parts.size());
  for (std::size_t i = 0; i < shape.meshes().parts.size(); ++i) {
    const Mesh& m2 = *shape.meshes().parts[i].mesh;
    const Mesh& m1 = *block.meshes().parts[i].mesh;
    const Mesh& m0 = *footprint.meshes().parts[i].mesh;
    const double volume = validate(m2).volume;
    const Plan p2 = plan_of(m2), p1 = plan_of(m1), p0 = plan_of(m0);
    const double ground_area = p2.down_area;  // a set-back tower has no overhang: only its ground faces face down
    const ValidationReport v1 = validate(m1);
    EXPECT_TRUE(v1.ok()) << ::testing::PrintToString(v1.problems);
    EXPECT_NEAR(v1.volume, volume, 0.01 * volume);
    EXPECT_NEAR(p1.high - p1.low, volume / ground_area, 1e-6 * p2.high);  // the mean height
    EXPECT_LT(p1.high, p2.high);
    EXPECT_EQ(p1.low, p2.low);
    EXPECT_NEAR(p1.up_area, ground_area, 1e-9 * ground_area);
    // LOD0: the ground faces alone, facing up.
    EXPECT_NEAR(p0.up_area, ground_area, 1e-9 * ground_area);
    EXPECT_EQ(p0.down_area, 0.0);
    EXPECT_EQ(p0.high, p2.low);
    EXPECT_EQ(block.meshes().parts[i].building, shape.meshes().parts[i].building);
  }
  EXPECT_NE(block.result.outputs[0].hash, shape.result.outputs[0].hash);
  EXPECT_NE(footprint.result.outputs[0].hash, block.result.outputs[0].hash);
}

// A recipe that declares the graph input `lod` chooses by it, and the option
// binds it, so expressions read the level shown.
TEST_F(LevelsOfDetail, TheGraphInputLodChoosesTheLevel) {
  ASSERT_TRUE(graph_.add_input({"lod", &value_type<std::int64_t>(), "level of detail", Value::make<std::int64_t>(3)}));
  const Level by_input = at(std::nullopt, {{"lod", Value::make<std::int64_t>(1)}});
  EXPECT_EQ(by_input.result.lod, 1);
  const Level by_option = at(1, {{"lod", Value::make<std::int64_t>(2)}});  // the option wins
  EXPECT_EQ(by_option.result.outputs[0].hash, by_input.result.outputs[0].hash);
  EXPECT_EQ(at(std::nullopt).result.lod, kFullDetail);  // the input's default
}

TEST_F(LevelsOfDetail, ALevelOutsideZeroToThreeIsRefused) {
  const Level l = at(4);
  ASSERT_TRUE(l.result.has_errors());
  EXPECT_NE(l.result.diagnostics[0].message.find("levels are 0 (footprint)"), std::string::npos)
      << l.result.diagnostics[0].to_string();
}

}  // namespace
}  // namespace procex
