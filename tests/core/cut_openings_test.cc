// Openings cut into walls: the facade split's tiles of a box cut as holes with
// reveals, the result checked by the validator (closed, 2-manifold, oriented,
// no self-intersection) and its volume, faces and wall area in closed form;
// openings that cannot be cut are reported, not cut.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/geom/polygon3.h"
#include "core/mesh/validate.h"
#include "core/placement/cut_openings.h"
#include "core/placement/facade_split.h"
#include "core/placement/split.h"
#include "tests/core/mesh_fixtures.h"

namespace procex {
namespace {

Mesh box(double w, double d, double h) { return build_mesh(test::extrude({test::rectangle(0, 0, w, d)}, 0, h)); }

std::vector<std::string> tags_of(const Mesh& m) {
  std::vector<std::string> tags;
  for (Mesh::FaceHandle f : m.faces()) tags.push_back(face_kind(m, f) == FaceKind::Side ? "wall" : face_kind_name(face_kind(m, f)));
  return tags;
}

// Each tile, less `margin` on every side.
std::vector<Opening> openings_of(const Mesh& m, const std::string& floors, const std::string& bays, double margin) {
  FacadeSplitSpec spec;
  spec.floors = parse_split(floors);
  spec.bays = parse_split(bays);
  std::vector<Opening> out;
  for (const FacadeTile& t : split_facades(m, [](Mesh::FaceHandle) { return true; }, spec).tiles)
    out.push_back({t.edge_id, t.frame, {-t.width / 2 + margin, margin}, {t.width / 2 - margin, t.height - margin}});
  return out;
}

struct Sums {
  std::size_t faces = 0;
  double area = 0;
};
Sums tagged(const Mesh& m, const std::string& tag) {
  Sums s;
  for (Mesh::FaceHandle f : m.faces()) {
    if (face_tag(m, f) != tag) continue;
    std::vector<glm::dvec3> pts;
    for (auto v : m.fv_range(f)) pts.emplace_back(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
    ++s.faces;
    s.area += glm::length(newell_normal(pts)) / 2;
  }
  return s;
}

// A 12 x 9 m box 10 m high, split into 3 m floors and bays of about 3 m: 42
// tiles (tests/core/facade_split_test.cc), each cut 2 x 2 m (0.5 m of wall
// kept around it), 0.25 m deep.
TEST(CutOpenings, TheTilesOfABoxInClosedForm) {
  const Mesh m = box(12, 9, 10);
  const std::vector<Opening> openings = openings_of(m, "{3}*", "{~3}*", 0.5);
  ASSERT_EQ(openings.size(), 42u);
  CutReport report;
  const Mesh cut = cut_openings(m, tags_of(m), openings, {0.25, "reveal"}, report);
  EXPECT_EQ(report.cut, 42u);
  EXPECT_TRUE(report.skipped.empty()) << report.skipped[0];
  const ValidationReport v = validate(cut);
  EXPECT_TRUE(v.ok()) << (v.problems.empty() ? "" : v.problems[0]);
  // The volume loses each recess: 42 x 2 x 2 x 0.25 m3.
  EXPECT_NEAR(v.volume, 12 * 9 * 10 - 42 * 2 * 2 * 0.25, 1e-9);
  // Per opening four reveals (2 x 0.25 m each) and a back (2 x 2 m).
  const Sums reveals = tagged(cut, "reveal");
  EXPECT_EQ(reveals.faces, 42u * 5u);
  EXPECT_NEAR(reveals.area, 42 * (4 * 2 * 0.25 + 2 * 2), 1e-9);
  // The walls lose the holes' area; base and cap are as they were.
  EXPECT_NEAR(tagged(cut, "wall").area, 2 * (12 + 9) * 10 - 42 * 2 * 2, 1e-9);
  EXPECT_NEAR(tagged(cut, "cap").area, 12 * 9, 1e-9);
  EXPECT_EQ(tagged(cut, "cap").faces, 1u);
  // Every face keeps its edge: the recess faces the edge of the wall they are cut into.
  for (Mesh::FaceHandle f : cut.faces())
    if (face_kind(cut, f) == FaceKind::Side) {
      EXPECT_GE(source_edge(cut, f), 0);
    }
}

// A 12 x 9 m block 10 m high with an 8 x 5 m tier set back 2 m on every side
// up to 20 m: one solid (the lower roof a ring around the tier). Walls on
// edges 0..3 below, 4..7 above.
Mesh stepped() {
  Surface s;
  const auto lower = test::rectangle(0, 0, 12, 9), upper = test::rectangle(2, 2, 10, 7);
  for (const auto& [loop, z] : {std::pair{lower, 0.0}, {lower, 10.0}, {upper, 10.0}, {upper, 20.0}})
    for (const glm::dvec2& p : loop) s.vertices.push_back({p.x, p.y, z});
  auto ring = [](std::uint32_t first, bool reversed) {
    std::vector<std::uint32_t> r{first, first + 1, first + 2, first + 3};
    if (reversed) std::reverse(r.begin(), r.end());
    return r;
  };
  s.faces.push_back({FaceKind::Base, -1, {ring(0, true)}, {}});
  s.faces.push_back({FaceKind::Cap, -1, {ring(4, false), ring(8, true)}, {}});
  s.faces.push_back({FaceKind::Cap, -1, {ring(12, false)}, {}});
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t n = (k + 1) % 4;
    s.faces.push_back({FaceKind::Side, static_cast<std::int32_t>(k), {{k, n, 4 + n, 4 + k}}, {}});
    s.faces.push_back({FaceKind::Side, static_cast<std::int32_t>(4 + k), {{8 + k, 8 + n, 12 + n, 12 + k}}, {}});
  }
  return build_mesh(s);
}

// Floors of 4 m and bays of about 2 m: 2 x (6 + 5) x 2 tiles below, 2 x (4 +
// 3) x 2 above (facade_split_test), each cut 0.4 m inside its tile, 0.3 m deep.
TEST(CutOpenings, ASetBackTowerStaysClosed) {
  const Mesh m = stepped();
  const ValidationReport before = validate(m);
  ASSERT_TRUE(before.ok());
  ASSERT_NEAR(before.volume, 12 * 9 * 10 + 8 * 5 * 10, 1e-9);
  const std::vector<Opening> openings = openings_of(m, "{4}*", "{~2}*", 0.4);
  ASSERT_EQ(openings.size(), 44u + 28u);
  CutReport report;
  const Mesh cut = cut_openings(m, tags_of(m), openings, {0.3, "reveal"}, report);
  EXPECT_EQ(report.cut, openings.size());
  const ValidationReport after = validate(cut);
  EXPECT_TRUE(after.ok()) << (after.problems.empty() ? "" : after.problems[0]);
  double recesses = 0;
  for (const Opening& o : openings) recesses += (o.hi.x - o.lo.x) * (o.hi.y - o.lo.y) * 0.3;
  // Bays 12 / 6 = 2 and 9 / 5 = 1.8 m wide below, 8 / 4 = 2 and 5 / 3 m above; openings 0.8 m narrower, 3.2 m high.
  EXPECT_NEAR(recesses, 0.3 * 3.2 * (2 * 6 * 2 * 1.2 + 2 * 5 * 2 * 1.0 + 2 * 4 * 2 * 1.2 + 2 * 3 * 2 * (5.0 / 3 - 0.8)), 1e-9);
  EXPECT_NEAR(after.volume, before.volume - recesses, 1e-9);
}

std::string only_refusal(const Mesh& m, const std::vector<Opening>& openings, double depth, std::size_t cut_expected) {
  CutReport report;
  const Mesh cut = cut_openings(m, tags_of(m), openings, {depth, "reveal"}, report);
  EXPECT_EQ(report.cut, cut_expected);
  EXPECT_TRUE(validate(cut).ok());
  return report.skipped.size() == 1 ? report.skipped[0] : "skipped " + std::to_string(report.skipped.size());
}

TEST(CutOpenings, WhatCannotBeCutIsReportedNotCut) {
  const Mesh m = box(12, 9, 10);
  // Edge 0 runs along y = 0 from x = 0 to 12, its outside towards -y.
  const Frame front{{6, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
  const Opening door{0, front, {-1, 0.0}, {1, 2.2}};  // meets the ground: no wall under it
  const Opening window{0, front, {-1, 1}, {1, 2.5}};
  const Opening past_corner{0, front, {5, 1}, {6.5, 2.5}};
  const Opening overlapping{0, front, {0.5, 2}, {2, 3}};
  EXPECT_NE(only_refusal(m, {door}, 0.2, 0).find("not inside one face of its edge with wall left around it"),
            std::string::npos);
  EXPECT_NE(only_refusal(m, {past_corner}, 0.2, 0).find("not inside one face"), std::string::npos);
  EXPECT_NE(only_refusal(m, {window, overlapping}, 0.2, 1).find("overlaps or comes too near an opening cut before it"),
            std::string::npos);
  // 9.5 m deep reaches through the 9 m box to the back wall.
  EXPECT_NE(only_refusal(m, {window}, 9.5, 0).find("would reach face"), std::string::npos);
  // Near the corner, a window on the side wall (edge 1, x = 12) and one on the front meet behind it.
  const Frame side{{12, 4.5, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
  const Opening front_corner{0, front, {4.5, 1}, {5.8, 2.5}};
  const Opening side_corner{1, side, {-4.3, 1}, {-3, 2.5}};
  EXPECT_NE(only_refusal(m, {front_corner, side_corner}, 1.0, 1).find("overlaps or comes too near"), std::string::npos);
  EXPECT_EQ(only_refusal(m, {front_corner, side_corner}, 0.1, 2), "skipped 0");
}

}  // namespace
}  // namespace procex
