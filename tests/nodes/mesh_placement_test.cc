// The Mesh Placement node on a 10 x 6 m block with 6 m walls (rows and
// grids are clipped to the faces, so the anchors lie on them) whose anchors are
// resolved by hand (tests/nodes/hand_anchors.h): counts and positions per
// mode, absent anchors as warnings, mistakes as errors naming what is wrong.
#include <filesystem>

#include <gtest/gtest.h>

#include "core/placement/box.h"
#include "nodes/values.h"
#include "tests/nodes/hand_anchors.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using test::run_node;

const Footprint kPlan = make_footprint({{{0, 0}, {10, 0}, {10, 6}, {0, 6}}}, 0);

// Extrude's block with anchors "sill" (1 m up, mid-wall) and "eave" (3 m up)
// on every wall; `absent` edges lost at the sill.
Value block(const std::vector<int>& absent = {}) {
  const auto r = run_node("Extrude", {{"max_height", Value::make(6.0)}}, {{"footprint", Value::make(kPlan)}});
  EXPECT_TRUE(r.ok()) << r.messages();
  MeshSet set = r.outputs.at(0).get<MeshSet>();
  set.parts.at(0).building = "b7";
  set.parts[0].anchors = test::wall_anchors(kPlan, "sill", 1.0, 0.5, absent);
  for (const ResolvedAnchor& a : test::wall_anchors(kPlan, "eave", 3.0, 0.5)) set.parts[0].anchors.push_back(a);
  return Value::make(set);
}

test::NodeRun place(std::map<std::string, Value> params, const Value& mesh = block()) {
  params.try_emplace("file", Value::make(std::string("mesh_window_frame.obj")));
  return run_node("Mesh Placement", params, {{"mesh", mesh}}, PROCEX_TEST_DATA);
}

Value mode(const char* m) { return Value::make(EnumValue{m}); }

const TaggedMesh& part(const test::NodeRun& r) { return r.outputs.at(0).get<MeshSet>().parts.at(0); }

Box3 instance_bounds(const TaggedMesh& p, std::size_t i) {
  PlacementResult one;
  one.meshes = p.placed.meshes;
  one.instances = {p.placed.instances.at(i)};
  return bounds(flatten(one));
}

TEST(MeshPlacement, OneAtEachWallsAnchor) {
  const auto r = place({{"anchor", Value::make(std::string("sill"))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const TaggedMesh& p = part(r);
  ASSERT_EQ(p.placed.instances.size(), 4u);
  ASSERT_EQ(p.placed.meshes.size(), 1u);
  EXPECT_EQ(p.placed.meshes[0].name, "mesh_window_frame");  // the file's name when `name` is empty
  // Front wall (edge 0, y = 0): centred on x = 5, standing on z = 1, in front of the wall.
  const Box3 front = instance_bounds(p, 0);
  EXPECT_NEAR((front.lo.x + front.hi.x) / 2, 5, 1e-9);
  EXPECT_NEAR(front.lo.z, 1, 1e-9);
  EXPECT_NEAR(front.hi.y, 0, 1e-9);
  EXPECT_EQ(p.placed.instances[1].source_edge, 1);
  EXPECT_EQ(p.mesh->n_faces(), block().get<MeshSet>().parts[0].mesh->n_faces());  // the building's own mesh as it was
}

TEST(MeshPlacement, RowsFollowEachFacadesLength) {
  const auto r = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("row")},
                        {"column_spacing", Value::make(2.0)}, {"tag", Value::make(std::string("window"))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const TaggedMesh& p = part(r);
  ASSERT_EQ(p.placed.instances.size(), 5u + 3u + 5u + 3u);  // every 2 m: 10 m walls get 5, 6 m walls 3
  EXPECT_EQ(p.placed.instances[0].tag, "window");
  const auto counted = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("row")},
                              {"columns", Value::make<std::int64_t>(2)}});
  EXPECT_EQ(part(counted).placed.instances.size(), 8u);
}

TEST(MeshPlacement, GridAndStretch) {
  const auto grid = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("grid")},
                           {"columns", Value::make<std::int64_t>(2)}, {"rows", Value::make<std::int64_t>(3)},
                           {"z_from", Value::make(1.0)}, {"z_to", Value::make(4.0)}});
  ASSERT_TRUE(grid.ok()) << grid.messages();
  EXPECT_EQ(part(grid).placed.instances.size(), 4u * 2u * 3u);
  EXPECT_EQ(grid.outputs.at(1).get<std::int64_t>(), 0);
  // Four 1.5 m rows from 1 m, windows centred in them: the fourth (5.5 to 7 m) passes the 6 m walls.
  const Value centred = Value::make(Vec3{0.5, 0.5, 0.0});
  const auto tall = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("grid")}, {"pivot", centred},
                           {"columns", Value::make<std::int64_t>(2)}, {"rows", Value::make<std::int64_t>(4)},
                           {"z_from", Value::make(1.0)}, {"z_to", Value::make(7.0)}});
  ASSERT_TRUE(tall.ok()) << tall.messages();
  EXPECT_EQ(part(tall).placed.instances.size(), 4u * 2u * 3u);
  EXPECT_EQ(tall.outputs.at(1).get<std::int64_t>(), 8);
  // z_to_top: up to each face's own top (6 m), whatever z_to says: (6 - 1) / 1.5 gives 3 rows.
  const auto top = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("grid")}, {"pivot", centred},
                          {"columns", Value::make<std::int64_t>(2)}, {"row_spacing", Value::make(1.5)},
                          {"z_from", Value::make(1.0)}, {"z_to", Value::make(100.0)}, {"z_to_top", Value::make(true)}});
  ASSERT_TRUE(top.ok()) << top.messages();
  EXPECT_EQ(part(top).placed.instances.size(), 4u * 2u * 3u);
  EXPECT_EQ(top.outputs.at(1).get<std::int64_t>(), 0);
  const auto pillar = place({{"anchor", Value::make(std::string("sill"))}, {"top_anchor", Value::make(std::string("eave"))},
                             {"mode", mode("stretch")}});
  ASSERT_TRUE(pillar.ok()) << pillar.messages();
  ASSERT_EQ(part(pillar).placed.instances.size(), 4u);
  const Box3 b = instance_bounds(part(pillar), 0);
  EXPECT_NEAR(b.lo.z, 1, 1e-9);  // from the sill
  EXPECT_NEAR(b.hi.z, 3, 1e-9);  // to the eave
}

TEST(MeshPlacement, AbsentAnchorsAreWarningsNotErrors) {
  const auto r = place({{"anchor", Value::make(std::string("sill"))}}, block({1, 3}));
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_EQ(part(r).placed.instances.size(), 2u);
  ASSERT_EQ(r.diagnostics.size(), 2u) << r.messages();
  EXPECT_NE(r.messages().find("building b7: "), std::string::npos) << r.messages();
  EXPECT_NE(r.messages().find("edge gone"), std::string::npos) << r.messages();
}

TEST(MeshPlacement, InputWithoutAnchorsPassesWithAWarning) {
  const auto plain = run_node("Extrude", {{"max_height", Value::make(6.0)}}, {{"footprint", Value::make(kPlan)}});
  const auto r = place({}, plain.outputs.at(0));
  ASSERT_TRUE(r.ok()) << r.messages();
  EXPECT_TRUE(part(r).placed.instances.empty());
  EXPECT_NE(r.messages().find("carries no resolved anchors"), std::string::npos) << r.messages();
}

TEST(MeshPlacement, MistakesNameWhatIsWrong) {
  const auto typo = place({{"anchor", Value::make(std::string("sil"))}});
  EXPECT_FALSE(typo.ok());
  EXPECT_NE(typo.messages().find("no anchor named 'sil' on the input (there are 'eave', 'sill')"), std::string::npos)
      << typo.messages();
  const auto missing = place({{"anchor", Value::make(std::string("sill"))}, {"file", Value::make(std::string("nowhere.obj"))}});
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.messages().find("nowhere.obj"), std::string::npos) << missing.messages();
  const auto no_file = place({{"file", Value::make(std::string())}});
  EXPECT_NE(no_file.messages().find("file: no mesh file given"), std::string::npos) << no_file.messages();
  const auto bad = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("grid")},
                          {"z_from", Value::make(4.0)}, {"z_to", Value::make(1.0)}});
  EXPECT_FALSE(bad.ok());
  EXPECT_NE(bad.messages().find("sill"), std::string::npos) << bad.messages();
}

// A batch places the same window on thousands of buildings: read once, shared.
TEST(MeshPlacement, TheFileIsReadOnceAndShared) {
  const auto a = place({{"anchor", Value::make(std::string("sill"))}});
  const auto b = place({{"anchor", Value::make(std::string("eave"))}});
  ASSERT_TRUE(a.ok() && b.ok()) << a.messages() << b.messages();
  EXPECT_EQ(part(a).placed.meshes.at(0).mesh, part(b).placed.meshes.at(0).mesh);
}

}  // namespace
}  // namespace procex

namespace procex {
namespace {

// A legal recipe that asks for more than a building can hold (300 x 300 on
// each of four walls: 360,000 windows) is refused with a reason, not run
// until memory runs out.
TEST(MeshPlacement, ABuildingHasABudget) {
  const auto huge = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("grid")},
                           {"columns", Value::make<std::int64_t>(300)}, {"rows", Value::make<std::int64_t>(300)},
                           {"z_from", Value::make(1.0)}, {"z_to", Value::make(4.0)}});
  EXPECT_FALSE(huge.ok());
  EXPECT_NE(huge.messages().find("more than 100000 placed meshes"), std::string::npos) << huge.messages();
  const auto tiny_spacing = place({{"anchor", Value::make(std::string("sill"))}, {"mode", mode("row")},
                                   {"column_spacing", Value::make(1e-300)}});
  EXPECT_FALSE(tiny_spacing.ok());
  EXPECT_EQ(tiny_spacing.messages().find("-9223372036854775808"), std::string::npos) << tiny_spacing.messages();
}

}  // namespace
}  // namespace procex
