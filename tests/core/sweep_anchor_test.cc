// Anchor events: an anchor resolves on every selected edge that still exists
// at its height, to a position and frame checked against hand-computed
// numbers; edges gone by then, or plan anchors beyond the edge's ends, are
// absent with a reason; malformed anchors are refused naming the anchor.
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/geom/footprint.h"
#include "core/sweep/sweep.h"

namespace procex {
namespace {

void expect_near(glm::dvec3 got, glm::dvec3 want, const std::string& what) {
  EXPECT_NEAR(got.x, want.x, 1e-9) << what;
  EXPECT_NEAR(got.y, want.y, 1e-9) << what;
  EXPECT_NEAR(got.z, want.z, 1e-9) << what;
}

// A 20 x 10 house: walls to 3 m, then a 45 degree hip roof (ridge at 8 m).
Footprint house() {
  Footprint fp = make_footprint({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}, 45.0);
  fp.profiles = {{"hip", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}}};
  for (EdgeSpec& e : fp.loops[0].edges) e.profile = 0;
  return fp;
}

Surface sweep_with(const Footprint& fp, std::vector<Anchor> anchors) {
  SweepOptions o;
  o.anchors = std::move(anchors);
  return sweep(fp, o);
}

TEST(Anchors, MidFacadeOnEveryWall) {
  const Surface s = sweep_with(house(), {{"window", {PlanAnchor::Mode::Fraction, 0.5}, 1.5, -1, {}}});
  ASSERT_EQ(s.anchors.size(), 4u);
  for (const ResolvedAnchor& r : s.anchors) EXPECT_TRUE(r.present) << r.reason;
  const ResolvedAnchor& front = s.anchors[0];
  EXPECT_EQ(front.name, "window");
  EXPECT_EQ(front.edge_id, 0);
  expect_near(front.frame.origin, {10, 0, 1.5}, "origin");
  expect_near(front.frame.along, {1, 0, 0}, "along");
  expect_near(front.frame.normal, {0, -1, 0}, "normal");
  expect_near(front.frame.up, {0, 0, 1}, "up");
  expect_near(front.span_from, {0, 0, 1.5}, "span start");
  expect_near(front.span_to, {20, 0, 1.5}, "span end");
  expect_near(s.anchors[1].frame.origin, {20, 5, 1.5}, "right wall");
  expect_near(s.anchors[2].frame.origin, {10, 10, 1.5}, "back wall");
}

TEST(Anchors, OnTheRoofTheFractionIsOfTheEdgeThere) {
  // At 5 m the roof has moved 2 m in: the front edge runs from (2, 2) to (18, 2).
  const Surface s = sweep_with(house(), {{"dormer", {PlanAnchor::Mode::Fraction, 0.25}, 5.0, -1, {0}}});
  ASSERT_EQ(s.anchors.size(), 1u);
  const ResolvedAnchor& r = s.anchors[0];
  ASSERT_TRUE(r.present) << r.reason;
  expect_near(r.frame.origin, {6, 2, 5}, "origin");
  expect_near(r.frame.normal, glm::dvec3{0, -1, 1} / std::sqrt(2.0), "normal");
  expect_near(r.frame.up, glm::dvec3{0, 1, 1} / std::sqrt(2.0), "up the slope");
  expect_near(glm::cross(r.frame.along, r.frame.up), r.frame.normal, "right-handed");
  expect_near(r.span_from, {2, 2, 5}, "span start");
  expect_near(r.span_to, {18, 2, 5}, "span end");
}

TEST(Anchors, AbsoluteAnchorsAreCarriedUpTheFace) {
  // 3 m from the start of the front edge, at 5 m: still x = 3, on the roof.
  const Surface s = sweep_with(house(), {{"a", {PlanAnchor::Mode::FromStart, 3.0}, 5.0, -1, {0}},
                                         {"b", {PlanAnchor::Mode::FromEnd, 1.0}, 5.0, -1, {0}},
                                         {"c", {PlanAnchor::Mode::FromStart, 1.0}, 5.0, -1, {0}}});
  ASSERT_EQ(s.anchors.size(), 3u);
  ASSERT_TRUE(s.anchors[0].present);
  expect_near(s.anchors[0].frame.origin, {3, 2, 5}, "from start");
  // 1 m from the end is x = 19, beyond the roof edge's end at x = 18 there.
  EXPECT_FALSE(s.anchors[1].present);
  EXPECT_NE(s.anchors[1].reason.find("beyond the ends of edge 0"), std::string::npos) << s.anchors[1].reason;
  EXPECT_FALSE(s.anchors[2].present);
}

TEST(Anchors, AboveTheRoofIsAbsentNotAnError) {
  const Surface s = sweep_with(house(), {{"chimney top", {PlanAnchor::Mode::Fraction, 0.5}, 9.0, -1, {}}});
  ASSERT_EQ(s.anchors.size(), 4u);
  for (const ResolvedAnchor& r : s.anchors) {
    EXPECT_FALSE(r.present);
    EXPECT_FALSE(r.reason.empty());
  }
}

TEST(Anchors, ShortSidesVanishBeforeTheLongOnes) {
  // At 7.5 m the short (hip) faces span 1 m; the long ones 11 m.
  const Surface s = sweep_with(house(), {{"vent", {PlanAnchor::Mode::Fraction, 0.5}, 7.5, -1, {}}});
  ASSERT_EQ(s.anchors.size(), 4u);
  for (const ResolvedAnchor& r : s.anchors) ASSERT_TRUE(r.present) << r.reason;
  EXPECT_NEAR(glm::length(s.anchors[0].span_to - s.anchors[0].span_from), 11.0, 1e-9);
  EXPECT_NEAR(glm::length(s.anchors[1].span_to - s.anchors[1].span_from), 1.0, 1e-9);
}

TEST(Anchors, SelectedByProfile) {
  Footprint fp = house();
  fp.profiles.push_back({"gable end", {{0, 0}, {0, 3}, {0, 30}}, {"wall", "gable"}});
  fp.loops[0].edges[1].profile = 1;
  fp.loops[0].edges[3].profile = 1;
  const Surface s = sweep_with(fp, {{"attic window", {PlanAnchor::Mode::Fraction, 0.5}, 6.0, 1, {}}});
  ASSERT_EQ(s.anchors.size(), 2u);
  EXPECT_EQ(s.anchors[0].edge_id, 1);
  EXPECT_EQ(s.anchors[1].edge_id, 3);
  ASSERT_TRUE(s.anchors[0].present) << s.anchors[0].reason;
  expect_near(s.anchors[0].frame.origin, {20, 5, 6}, "gable window");
  expect_near(s.anchors[0].frame.normal, {1, 0, 0}, "gable normal");
}

TEST(Anchors, MovingAFootprintVertexMovesTheAnchor) {
  Footprint fp = house();
  fp.loops[0].points[1].x = 30;  // the front edge now runs to x = 30
  fp.loops[0].points[2].x = 30;
  const Surface s = sweep_with(fp, {{"door", {PlanAnchor::Mode::Fraction, 0.5}, 1.0, -1, {0}}});
  ASSERT_TRUE(s.anchors[0].present);
  expect_near(s.anchors[0].frame.origin, {15, 0, 1}, "door follows the edge");
}

TEST(Anchors, MalformedAnchorsNameThemselves) {
  auto message = [](Anchor a) {
    try {
      sweep_with(house(), {std::move(a)});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({"w", {PlanAnchor::Mode::Fraction, 1.5}, 1.0, -1, {}}).find("anchor 'w': fraction"),
            std::string::npos);
  EXPECT_NE(message({"w", {PlanAnchor::Mode::Fraction, 0.5}, -1.0, -1, {}}).find("anchor 'w': height"),
            std::string::npos);
  EXPECT_NE(message({"w", {PlanAnchor::Mode::Fraction, 0.5}, 1.0, 7, {}}).find("selects no edge"), std::string::npos);
  EXPECT_NE(message({"w", {PlanAnchor::Mode::FromStart, std::nan("")}, 1.0, -1, {}}).find("not a finite"),
            std::string::npos);
}

}  // namespace
}  // namespace procex
