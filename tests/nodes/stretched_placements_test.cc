// Meshes stretched between two anchors on the same wall, end to end through
// the sample recipes: buttresses around an octagonal chapter house
// (samples/buttresses.pxg) and pillars under a jettied upper storey
// (samples/pillars.pxg), each checked against the footprint Extrude swept.
#include <gtest/gtest.h>

#include "tests/nodes/anchored_recipe.h"

namespace procex {
namespace {

using test::building;
using test::Extent;
using test::messages;
using test::Recipe;
using test::Wall;

// The footprint Extrude swept (Assign Profiles' output) as walls, each with its profile's name.
std::vector<std::pair<Wall, std::string>> swept_walls(Recipe& r) {
  const Value v = r.port(r.node("Assign Profiles"), 0);
  const Footprint& fp = v.get<Footprint>();
  std::vector<std::pair<Wall, std::string>> out;
  const Loop& loop = fp.loops.at(0);
  for (std::size_t k = 0; k < loop.points.size(); ++k)
    out.push_back({{loop.points[k], loop.points[(k + 1) % loop.points.size()]},
                   fp.profiles.at(static_cast<std::size_t>(loop.edges[k].profile)).name});
  return out;
}

// One buttress per edge of profile `chapter`, standing on the ground in the
// middle of its wall, 6 m high, its foot 1.2 m deep.
void expect_buttresses(Recipe& r, std::size_t sides) {
  const EvalResult result = r.run();
  const TaggedMesh& part = building(result);
  const auto walls = swept_walls(r);
  ASSERT_EQ(walls.size(), sides);
  std::size_t chapter = 0;
  for (const auto& [wall, profile] : walls) chapter += profile == "chapter" ? 1 : 0;
  EXPECT_EQ(chapter, sides - 1);  // all but the entrance front
  ASSERT_EQ(part.placed.instances.size(), chapter) << messages(result);
  for (const Instance& in : part.placed.instances) {
    ASSERT_GE(in.source_edge, 0);
    const auto& [wall, profile] = walls.at(static_cast<std::size_t>(in.source_edge));
    EXPECT_EQ(profile, "chapter");
    const Extent x = test::extent_on(wall, part.placed, in);
    EXPECT_NEAR(x.z_lo, 0.0, 1e-9);
    EXPECT_NEAR(x.z_hi, 6.0, 1e-9);
    EXPECT_NEAR(x.out_lo, 0.0, 1e-9);
    EXPECT_NEAR(x.out_hi, 1.2, 1e-9);
    EXPECT_NEAR((x.along_lo + x.along_hi) / 2, wall.length() / 2, 1e-9);
    EXPECT_NEAR(x.along_hi - x.along_lo, 0.6, 1e-9);
  }
}

TEST(Buttresses, OneOnEveryEdgeOfTheirProfileAroundTheChapterHouse) {
  Recipe r("buttresses");
  expect_buttresses(r, 8);
}

TEST(Buttresses, FollowTheFootprintWhenItHasMoreSides) {
  Recipe r("buttresses");
  ASSERT_TRUE(r.g.set_exposed("sides", Value::make<std::int64_t>(12)));
  expect_buttresses(r, 12);
}

// Pillars stand under the 1.5 m overhang of the upper storey, from the ground
// to the soffit at 3 m, 1.25 m out of the wall: one at every corner, one in
// the middle of every facade.
TEST(Pillars, CarryTheJettyAtTheCornersAndMidFacades) {
  Recipe r("pillars");
  const EvalResult result = r.run();
  const TaggedMesh& part = building(result);
  const auto walls = swept_walls(r);
  ASSERT_EQ(walls.size(), 4u);
  ASSERT_EQ(part.placed.instances.size(), 8u) << messages(result);
  std::map<std::int32_t, std::vector<double>> centres;  // along each wall
  for (const Instance& in : part.placed.instances) {
    const Wall& wall = walls.at(static_cast<std::size_t>(in.source_edge)).first;
    const Extent x = test::extent_on(wall, part.placed, in);
    EXPECT_NEAR(x.z_lo, 0.0, 1e-9);
    EXPECT_NEAR(x.z_hi, 3.0, 1e-9);
    EXPECT_NEAR(x.out_lo, 1.0, 1e-9);  // under the soffit, which reaches 1.5 m out
    EXPECT_NEAR(x.out_hi, 1.5, 1e-9);
    centres[in.source_edge].push_back((x.along_lo + x.along_hi) / 2);
  }
  for (const auto& [edge, along] : centres) {
    SCOPED_TRACE("edge " + std::to_string(edge));
    ASSERT_EQ(along.size(), 2u);
    EXPECT_NEAR(along[0], -1.25, 1e-9);  // under the corner of the overhang
    EXPECT_NEAR(along[1], walls.at(static_cast<std::size_t>(edge)).first.length() / 2, 1e-9);
  }
}

}  // namespace
}  // namespace procex
