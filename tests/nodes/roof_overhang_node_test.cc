// Roof Overhang through a real graph: the building from Extrude is handed on
// as it was (the same shared mesh), followed by its slab, both closed; the
// node's mistakes name the node's parameter or the tags it looked for.
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

#include "core/mesh/validate.h"
#include "nodes/support/profile_presets.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

using test::run_node;

// A 12 x 20 m gabled building with flush walls 4 m high and 45-degree slopes:
// edges 0 and 2 (12 m) are the gables.
MeshSet gabled() {
  Footprint plan = make_footprint({{{0, 0}, {12, 0}, {12, 20}, {0, 20}}}, 0);
  plan.profiles = {make_preset("flush_eave", {.height = 4, .pitch_deg = 45, .roof_height = 12}),
                   make_preset("gable_end", {.roof_height = 30})};
  for (int e : {1, 3}) plan.loops[0].edges[e].profile = 0;
  for (int e : {0, 2}) plan.loops[0].edges[e].profile = 1;
  const auto extruded = run_node("Extrude", {}, {{"footprint", Value::make(plan)}});
  EXPECT_TRUE(extruded.ok()) << extruded.messages();
  return extruded.outputs.at(0).get<MeshSet>();
}

TEST(RoofOverhangNode, AddsAClosedSlabAndLeavesTheBuilding) {
  const MeshSet building = gabled();
  ASSERT_EQ(building.parts.size(), 1u);
  const auto r = run_node("Roof Overhang", {{"eave", Value::make(0.6)}, {"verge", Value::make(0.4)}, {"thickness", Value::make(0.25)}},
                          {{"mesh", Value::make(building)}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const MeshSet& out = r.outputs.at(0).get<MeshSet>();
  ASSERT_EQ(out.parts.size(), 2u);
  EXPECT_EQ(out.parts[0].mesh, building.parts[0].mesh);  // not even copied
  EXPECT_TRUE(validate(*out.parts[0].mesh).ok());
  const TaggedMesh& slab = *(out.parts.end() - 1);
  EXPECT_TRUE(validate(*slab.mesh).ok());
  EXPECT_EQ(std::set<std::string>(slab.tags.begin(), slab.tags.end()),
            (std::set<std::string>{"roof", "fascia", "soffit", "underside"}));
  EXPECT_EQ(slab.face_tags.size(), slab.mesh->n_faces());
  double lo_x = HUGE_VAL, lo_y = HUGE_VAL;
  for (auto v : slab.mesh->vertices()) lo_x = std::min(lo_x, slab.mesh->point(v)[0]), lo_y = std::min(lo_y, slab.mesh->point(v)[1]);
  EXPECT_NEAR(lo_x, -0.6, 1e-9);  // eaves past the long walls
  EXPECT_NEAR(lo_y, -0.4, 1e-9);  // verges past the gables
  // 0.25 thick square to slopes of 1 over 13.2 x 20.8 m in plan.
  EXPECT_NEAR(validate(*slab.mesh).volume, 0.25 * std::sqrt(2.0) * 13.2 * 20.8, 1e-6);
}

TEST(RoofOverhangNode, TheSlabKeepsTheBuildingsMaterials) {
  const auto painted = run_node("Material", {{"tag", Value::make(std::string("roof"))}, {"roughness", Value::make(0.35)}},
                                {{"mesh", Value::make(gabled())}});
  ASSERT_TRUE(painted.ok()) << painted.messages();
  const auto r = run_node("Roof Overhang", {}, {{"mesh", painted.outputs.at(0)}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const MeshSet& out = r.outputs.at(0).get<MeshSet>();
  ASSERT_EQ(out.parts.size(), 2u);
  const Materials& slab = materials_of(out.parts[1].materials);
  ASSERT_EQ(slab.count("roof"), 1u);
  EXPECT_DOUBLE_EQ(slab.at("roof").roughness, 0.35);
}

// What a run with these parameters says: its diagnostics, or why the graph refused them.
std::string mistake(const std::map<std::string, Value>& params, const Value& building) {
  try {
    const auto r = run_node("Roof Overhang", params, {{"mesh", building}});
    return r.ok() ? "accepted" : r.messages();
  } catch (const std::exception& e) {
    return e.what();
  }
}

TEST(RoofOverhangNode, MistakesNameTheParameterOrTheTags) {
  const Value building = Value::make(gabled());
  // Out of range: refused by the declaration, naming the parameter.
  EXPECT_NE(mistake({{"eave", Value::make(-1.0)}}, building).find("parameter 'eave' = -1 is outside its range [0, 20]"),
            std::string::npos);
  EXPECT_NE(mistake({{"verge", Value::make(1e9)}}, building).find("parameter 'verge' = 1e+09 is outside its range"),
            std::string::npos);
  // NaN is in no range to refuse it: the node refuses it.
  const std::string nan = mistake({{"thickness", Value::make(std::nan(""))}}, building);
  EXPECT_NE(nan.find("Roof Overhang"), std::string::npos) << nan;
  EXPECT_NE(nan.find("thickness must be a finite number above 0, not nan"), std::string::npos) << nan;
  const std::string untagged = mistake({{"roof_tags", Value::make(std::string("roofs"))}}, building);
  EXPECT_NE(untagged.find("no face is tagged roofs (the faces' tags: 'base', 'gable', 'roof', 'wall')"), std::string::npos)
      << untagged;
}

TEST(RoofOverhangNode, AMansardNamesBothSlopes) {
  Footprint plan = make_footprint({{{0, 0}, {12, 0}, {12, 9}, {0, 9}}}, 0);
  plan.profiles = {{"mansard", {{0, 0}, {0, 3}, {-1, 6}, {-4, 7}}, {"wall", "mansard", "roof"}}};
  for (auto& e : plan.loops[0].edges) e.profile = 0;
  const Value building = run_node("Extrude", {}, {{"footprint", Value::make(plan)}}).outputs.at(0);
  const auto r = run_node("Roof Overhang", {{"roof_tags", Value::make(std::string("mansard, roof"))}}, {{"mesh", building}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const Mesh& slab = *r.outputs.at(0).get<MeshSet>().parts.at(1).mesh;
  EXPECT_TRUE(validate(slab).ok());
  double low = HUGE_VAL;
  for (auto v : slab.vertices()) low = std::min(low, slab.point(v)[2]);
  EXPECT_NEAR(low, 3 - 3 * 0.5, 1e-9);  // the steep lower slope (3 up per 1 in) run 0.5 past the walls
}

TEST(RoofOverhangNode, SkipHandsARefusedBuildingOnAndCountsIt) {
  // The gabled building and a U whose arms stand 0.6 m apart, too close for eaves of 0.5.
  MeshSet both = gabled();
  Footprint u = make_footprint({{{0, 0}, {20, 0}, {20, 10}, {10.3, 10}, {10.3, 4}, {9.7, 4}, {9.7, 10}, {0, 10}}}, 0);
  u.profiles = {make_preset("flush_eave", {.height = 4, .pitch_deg = 45, .roof_height = 12})};
  for (auto& e : u.loops[0].edges) e.profile = 0;
  const auto extruded = run_node("Extrude", {}, {{"footprint", Value::make(u)}});
  ASSERT_TRUE(extruded.ok()) << extruded.messages();
  both.parts.push_back(extruded.outputs.at(0).get<MeshSet>().parts.at(0));
  const std::string refused = mistake({{"eave", Value::make(0.5)}}, Value::make(both));
  EXPECT_NE(refused.find("would fold over itself"), std::string::npos) << refused;
  const auto r = run_node("Roof Overhang", {{"eave", Value::make(0.5)}, {"on_refusal", Value::make(EnumValue{"skip"})}},
                          {{"mesh", Value::make(both)}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const MeshSet& out = r.outputs.at(0).get<MeshSet>();
  ASSERT_EQ(out.parts.size(), 3u);  // the gabled building, its slab, the U as it was
  EXPECT_EQ(out.parts[0].mesh, both.parts[0].mesh);
  EXPECT_TRUE(validate(*out.parts[1].mesh).ok());
  EXPECT_EQ(out.parts[2].mesh, both.parts[1].mesh);
  EXPECT_EQ(r.outputs.at(1).get<std::int64_t>(), 1);
  EXPECT_NE(r.messages().find("1 building(s) left without an overhang, the first: "), std::string::npos) << r.messages();
  EXPECT_NE(r.messages().find("would fold over itself"), std::string::npos) << r.messages();
}

}  // namespace
}  // namespace procex
