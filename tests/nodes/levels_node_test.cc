// Floors from a feature's levels: Levels raises a profile's wall to a number
// of floors and carries the roof up with it; Facade Split splits only the
// walls of the edges it is given (the street fronts), or all but those, with
// sizes a number parameter gives by name; Mesh Placement refuses a tile name
// no split gives.
#include <gtest/gtest.h>

#include <set>

#include "nodes/support/profile_presets.h"
#include "nodes/values.h"
#include "tests/nodes/node_runner.h"

namespace procex {
namespace {

using test::run_node;

Profile drawn(std::vector<glm::dvec2> points, std::vector<std::string> tags) {
  Profile p;
  p.name = "hip";
  p.points = std::move(points);
  p.tags = std::move(tags);
  return p;
}

TEST(Levels, RaisesTheWallAndCarriesTheRoofUp) {
  // A 6 m wall under a 45-degree roof 30 m high; 4 levels of 3.5 m make the wall 14 m.
  const auto r = run_node("Levels", {{"levels", Value::make(std::int64_t{4})}, {"floor_height", Value::make(3.5)}},
                          {{"profile", Value::make(drawn({{0, 0}, {0, 6}, {-30, 36}}, {"wall", "roof"}))}});
  ASSERT_TRUE(r.ok()) << r.messages();
  const Profile& p = r.outputs[0].get<Profile>();
  ASSERT_EQ(p.points.size(), 3u);
  EXPECT_EQ(p.points[0], glm::dvec2(0, 0));
  EXPECT_EQ(p.points[1], glm::dvec2(0, 14));
  EXPECT_EQ(p.points[2], glm::dvec2(-30, 44));
  EXPECT_EQ(p.tags, (std::vector<std::string>{"wall", "roof"}));
  EXPECT_EQ(p.name, "hip");
  // Fewer levels lower it: one level of 3 m.
  const auto low = run_node("Levels", {{"levels", Value::make(std::int64_t{1})}},
                            {{"profile", Value::make(drawn({{0, 0}, {0, 6}, {-30, 36}}, {"wall", "roof"}))}});
  ASSERT_TRUE(low.ok()) << low.messages();
  EXPECT_EQ(low.outputs[0].get<Profile>().points[2], glm::dvec2(-30, 33));
}

TEST(Levels, AProfileWithoutAWallIsANodeError) {
  const auto r = run_node("Levels", {}, {{"profile", Value::make(drawn({{0, 0}, {-3, 3}}, {"roof"}))}});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.messages().find("profile 'hip': its first segment is not a vertical wall"), std::string::npos)
      << r.messages();
}

// A 12 x 6 m block, walls 9 m high, split into 3 m floors and bays of about 3 m.
//   3 +-----------+ 2
//     |           |
//   0 +-----------+ 1     edge 0 is the street front
MeshSet block() {
  const Value plan = Value::make(make_footprint({{{0, 0}, {12, 0}, {12, 6}, {0, 6}}}, 0));
  const auto assigned = run_node("Assign Profiles", {{"rules", Value::make(std::string("* = vertical_wall"))}},
                                 {{"footprint", plan},
                                  {"profiles", Value::make(std::vector<Profile>{make_preset("vertical_wall", {9.0})})}});
  const auto extruded = run_node("Extrude", {}, {{"footprint", assigned.outputs.at(0)}});
  EXPECT_TRUE(extruded.ok()) << extruded.messages();
  return extruded.outputs.at(0).get<MeshSet>();
}

std::multiset<std::int32_t> tile_edges(const std::string& which) {
  const auto r = run_node("Facade Split",
                          {{"which_edges", Value::make(EnumValue{which})}, {"floors", Value::make(std::string("{3}*"))},
                           {"bays", Value::make(std::string("{~3}*"))}},
                          {{"mesh", Value::make(block())}, {"edges", Value::make(std::vector<std::int64_t>{0})}});
  EXPECT_TRUE(r.ok()) << r.messages();
  std::multiset<std::int32_t> out;
  for (const TaggedMesh& p : r.outputs.at(0).get<MeshSet>().parts)
    for (const FacadeTile& t : tiles_of(p)) out.insert(t.edge_id);
  return out;
}

TEST(FacadeSplit, OnlyTheListedEdgesOrAllButThem) {
  // 3 floors; 4 bays on the 12 m walls (edges 0 and 2), 2 on the 6 m walls (edges 1 and 3).
  const std::multiset<std::int32_t> all = tile_edges("all"), listed = tile_edges("listed"), unlisted = tile_edges("unlisted");
  EXPECT_EQ(all.size(), 3u * (4 + 2 + 4 + 2));
  EXPECT_EQ(listed.size(), 12u);
  EXPECT_EQ(listed.count(0), 12u);
  EXPECT_EQ(unlisted.count(0), 0u);
  EXPECT_EQ(unlisted.size(), all.size() - 12);
}

// A building without a street front: the door split keeps no tile, the window split does;
// placing doors there places none and is no error (a misspelt anchor outside tiles mode still is).
TEST(FacadeSplit, AnEmptySplitPlacesNothingAndIsNoError) {
  const auto windows = run_node("Facade Split", {{"name", Value::make(std::string("window"))}}, {{"mesh", Value::make(block())}});
  const auto doors = run_node("Facade Split",
                              {{"name", Value::make(std::string("door"))}, {"which_edges", Value::make(EnumValue{"listed"})}},
                              {{"mesh", windows.outputs.at(0)}, {"edges", Value::make(std::vector<std::int64_t>{})}});
  ASSERT_TRUE(doors.ok()) << doors.messages();
  EXPECT_EQ(doors.outputs.at(1).get<std::int64_t>(), 0);
  const auto placed = run_node("Mesh Placement",
                               {{"file", Value::make(std::string("meshes/door_textured.obj"))},
                                {"anchor", Value::make(std::string("door"))},
                                {"mode", Value::make(EnumValue{"tiles"})}},
                               {{"mesh", doors.outputs.at(0)}}, PROCEX_SAMPLES);
  ASSERT_TRUE(placed.ok()) << placed.messages();
  EXPECT_TRUE(placed.diagnostics.empty()) << placed.messages();
  EXPECT_TRUE(placed.outputs.at(0).get<MeshSet>().parts.at(0).placed.instances.empty());
  // A tile name no split upstream gives is a misspelling: an error naming it and the names there are.
  const auto typo = run_node("Mesh Placement",
                             {{"file", Value::make(std::string("meshes/door_textured.obj"))},
                              {"anchor", Value::make(std::string("dor"))},
                              {"mode", Value::make(EnumValue{"tiles"})}},
                             {{"mesh", doors.outputs.at(0)}}, PROCEX_SAMPLES);
  EXPECT_FALSE(typo.ok());
  EXPECT_NE(typo.messages().find("no Facade Split upstream makes tiles named 'dor' (they make 'door', 'window')"),
            std::string::npos)
      << typo.messages();
}

// Sizes by name: floor_height and bay_width are number parameters (an expression or an
// exposed parameter sets them), and the specs name them.
TEST(FacadeSplit, SizesNamedByNumberParameters) {
  const auto r = run_node("Facade Split",
                          {{"floors", Value::make(std::string("_floor_height {floor_height}*"))},
                           {"floor_height", Value::make(2.25)},
                           {"bays", Value::make(std::string("{bay_width}*"))},
                           {"bay_width", Value::make(4.0)}},
                          {{"mesh", Value::make(block())}});
  ASSERT_TRUE(r.ok()) << r.messages();
  // 9 m walls: a 2.25 m gap, then three floors of 2.25 m at 2.25, 4.5 and 6.75 m; 3 bays of 4 m on the
  // 12 m walls, 1 on the 6 m walls.
  std::set<double> sills;
  std::size_t n = 0;
  for (const FacadeTile& t : tiles_of(r.outputs.at(0).get<MeshSet>().parts.at(0))) {
    sills.insert(t.frame.origin.z);
    EXPECT_DOUBLE_EQ(t.height, 2.25);
    EXPECT_DOUBLE_EQ(t.width, 4.0);
    ++n;
  }
  EXPECT_EQ(sills, (std::set<double>{2.25, 4.5, 6.75}));
  EXPECT_EQ(n, 3u * (3 + 1 + 3 + 1));
  const auto unknown = run_node("Facade Split", {{"floors", Value::make(std::string("{floor_hieght}*"))}},
                                {{"mesh", Value::make(block())}});
  EXPECT_FALSE(unknown.ok());
  EXPECT_NE(unknown.messages().find("no size is named 'floor_hieght': sizes may also be named bay_width, floor_height"),
            std::string::npos)
      << unknown.messages();
}

}  // namespace
}  // namespace procex
