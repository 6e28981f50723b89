// Facade split: split specs over a length in closed form, and the tiles of a
// box and of a stepped tower counted and checked against the faces.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "core/mesh/mesh.h"
#include "core/placement/face_cover.h"
#include "core/placement/facade_split.h"
#include "core/placement/placement_error.h"
#include "core/placement/split.h"
#include "tests/core/mesh_fixtures.h"

namespace procex {
namespace {

std::string cells(const std::string& spec, double length) {
  std::string out;
  for (const SplitCell& c : split_length(parse_split(spec), length)) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s%g%s", out.empty() ? "" : " ", c.size, c.index < 0 ? "_" : "");
    out += buf;
  }
  return out;
}

TEST(Split, SizesFlexibleSizesGapsAndRepeats) {
  EXPECT_EQ(cells("4 {3}*", 14), "4 3 3 3");           // 1 m left over at the top
  EXPECT_EQ(cells("_1 {~3}* _1", 14), "1_ 3 3 3 3 1_");  // 12 / 3 bays
  EXPECT_EQ(cells("_1 {~3}* _1", 15.2), "1_ 3.3 3.3 3.3 3.3 1_");
  EXPECT_EQ(cells("_1 {~3}* _1", 16.6), "1_ 2.92 2.92 2.92 2.92 2.92 1_");  // 14.6 / 3 rounds to 5
  EXPECT_EQ(cells("{2 ~1}*3", 10), "2 1.33333 2 1.33333 2 1.33333");
  EXPECT_EQ(cells("~1 ~3", 8), "2 6");
  EXPECT_EQ(cells("{3}*", 2.9), "");
  EXPECT_EQ(cells("{3}*", 9), "3 3 3");  // exactly three, whatever the rounding
  const std::vector<SplitCell> c = split_length(parse_split("_0.5 {~3}* _0.5"), 10);
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c[1].index, 0);
  EXPECT_EQ(c[3].index, 2);
  EXPECT_EQ(c[4].index, -1);
  EXPECT_DOUBLE_EQ(c[4].start, 9.5);
}

TEST(Split, MistakesNameTheCharacter) {
  auto refusal = [](const std::string& spec) {
    try {
      parse_split(spec);
    } catch (const PlacementError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("3 {2}* {1}*"), "split '3 {2}* {1}*', character 8: only one repeated group is allowed");
  EXPECT_EQ(refusal("{3 {1}*}*"), "split '{3 {1}*}*', character 4: groups do not nest");
  EXPECT_EQ(refusal("{3}"), "split '{3}', character 4: '*' expected after the group ('{...}*' or '{...}*3')");
  EXPECT_EQ(refusal("{3"), "split '{3', character 1: the group is not closed with '}*'");
  EXPECT_EQ(refusal("3 m"), "split '3 m', character 3: a size in metres expected, not 'm'");
  EXPECT_EQ(refusal("{0}*"), "split '{0}*', character 1: a group repeated as often as it fits needs a size above zero");
  EXPECT_EQ(refusal("-2"), "split '-2', character 1: sizes are finite and not negative");
  EXPECT_EQ(refusal("{1}*"), "accepted");
  // Names are sizes only where the caller gives them; an unknown one is refused with those it knows.
  const SplitNames floor{{"floor_height", 3.5}, {"bay_width", 2.0}};
  EXPECT_EQ(split_length(parse_split("_floor_height {~floor_height}*", floor), 10.5).size(), 3u);
  EXPECT_DOUBLE_EQ(parse_split("_floor_height {~floor_height}*", floor).repeated.at(0).size, 3.5);
  EXPECT_TRUE(parse_split("_floor_height", floor).before.at(0).gap);
  try {
    parse_split("{floor}*", floor);
    ADD_FAILURE() << "accepted";
  } catch (const PlacementError& e) {
    EXPECT_EQ(std::string(e.what()), "split '{floor}*', character 2: no size is named 'floor': sizes may also be named bay_width, floor_height");
  }
  EXPECT_THROW(split_length(parse_split("{0.00001}*"), 10), PlacementError);  // a million cells
}

Mesh box(double w, double d, double h) { return build_mesh(test::extrude({test::rectangle(0, 0, w, d)}, 0, h)); }

FacadeTiles split_all(const Mesh& m, const std::string& floors, const std::string& bays) {
  FacadeSplitSpec spec;
  spec.floors = parse_split(floors);
  spec.bays = parse_split(bays);
  return split_facades(m, [](Mesh::FaceHandle) { return true; }, spec);
}

// A 12 x 9 m box 10 m high: floor(10 / 3) = 3 floors; round(12 / 3) = 4 and
// round(9 / 3) = 3 bays on the long and short walls: 2 * 3 * (4 + 3) = 42 tiles.
TEST(FacadeSplit, TilesOfABoxInClosedForm) {
  const Mesh m = box(12, 9, 10);
  FacadeTiles t = split_all(m, "{3}*", "{~3}*");
  EXPECT_EQ(t.tiles.size(), 42u);
  EXPECT_EQ(t.dropped, 0u);
  // Four floors of 3 m asked for: the fourth (9..12 m) passes the 10 m eaves on all 14 bays.
  t = split_all(m, "{3}*4", "{~3}*");
  EXPECT_EQ(t.tiles.size(), 42u);
  EXPECT_EQ(t.dropped, 14u);
  for (const FacadeTile& a : t.tiles) {
    EXPECT_DOUBLE_EQ(a.height, 3);
    EXPECT_NEAR(a.frame.origin.z, 3 * a.floor, 1e-12);
    EXPECT_NEAR(glm::length(glm::cross(a.frame.along, a.frame.up) - a.frame.normal), 0, 1e-12);
    EXPECT_NEAR(a.width, 3, 1e-12);
  }
}

// Two boxes stacked, the upper one set back 2 m on every side:
//     +--------+       10..20 m: 8 x 5
//     |        |
// +---+--------+---+    0..10 m: 12 x 9
// |                |
// +----------------+
// Floors of 4 m counted from the ground on every plane. The lower walls hold
// 0-4 and 4-8 (8-12 would pass their top, so it is not laid out there); on the
// upper walls 8-12 starts below their bottom (dropped), 12-16 and 16-20 fit.
// Bays of about 2 m: round(12 / 2) = 6, round(9 / 2) = 5 below; round(8 / 2) = 4,
// round(5 / 2) = 3 above.
TEST(FacadeSplit, NoTileAcrossASetBackOrAboveTheRoof) {
  Surface s = test::extrude({test::rectangle(0, 0, 12, 9)}, 0, 10);
  const Surface upper = test::extrude({test::rectangle(2, 2, 10, 7)}, 10, 20);
  // The two prisms as one mesh of two shells, the upper one's walls on edges 4..7.
  const auto offset = static_cast<std::uint32_t>(s.vertices.size());
  s.vertices.insert(s.vertices.end(), upper.vertices.begin(), upper.vertices.end());
  for (SurfaceFace f : upper.faces) {
    for (auto& loop : f.loops)
      for (auto& v : loop) v += offset;
    if (f.source_edge >= 0) f.source_edge += 4;
    s.faces.push_back(f);
  }
  const Mesh m = build_mesh(s);
  const FacadeTiles t = split_all(m, "{4}*", "{~2}*");
  std::size_t lower = 0, upper_tiles = 0;
  const FaceCover cover(m);
  for (const FacadeTile& a : t.tiles) {
    (a.edge_id < 4 ? lower : upper_tiles)++;
    // Checked against the faces: the tile's rectangle lies on its own edge's faces in its plane.
    EXPECT_TRUE(cover.covers(a.edge_id, a.frame, {-a.width / 2, 0}, {a.width / 2, a.height}));
    EXPECT_LE(a.frame.origin.z + a.height, a.edge_id < 4 ? 10 + 1e-9 : 20 + 1e-9);
    EXPECT_GE(a.frame.origin.z, a.edge_id < 4 ? 0 - 1e-9 : 10 - 1e-9);
    EXPECT_EQ(a.floor, static_cast<int>(std::lround(a.frame.origin.z / 4)));
  }
  EXPECT_EQ(lower, 2u * (6u + 5u) * 2u);
  EXPECT_EQ(upper_tiles, 2u * (4u + 3u) * 2u);
  EXPECT_EQ(t.dropped, 2u * (4u + 3u));
}

TEST(FaceCover, AreaInsideARectangle) {
  // An L-shaped polygon: 2x2 square with the top-right 1x1 cut away.
  const std::vector<glm::dvec2> l = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  EXPECT_DOUBLE_EQ(area_inside(l, {0, 0}, {2, 2}), 3);
  EXPECT_DOUBLE_EQ(area_inside(l, {0.5, 0.5}, {1.5, 1.5}), 0.75);
  EXPECT_DOUBLE_EQ(area_inside(l, {1.2, 1.2}, {1.8, 1.8}), 0);
  EXPECT_FALSE(covered({l}, {0.5, 0.5}, {1.5, 1.5}));
  EXPECT_TRUE(covered({l}, {0, 0}, {1, 2}));
  EXPECT_TRUE(covered({{{0, 0}, {1, 0}, {1, 2}, {0, 2}}, {{1, 0}, {2, 0}, {2, 1}, {1, 1}}}, {0, 0}, {2, 1}));  // two faces
}

}  // namespace
}  // namespace procex
