// Profile offsets (paper 3.3, fig. 5): the rewrite of each edge's profile,
// then the sweep of the result, checked against volumes and heights computed
// by hand (a rectangle's cross-section at each height is a rectangle, so the
// volume integrates its area) and by the full mesh validator.
#include "core/geom/profile_offset.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"

namespace procex {
namespace {

using testing::expect_valid;
using testing::faces_per_tag;

//   3 +-----------+ 2      edges: 0 bottom, 1 right, 2 top, 3 left
//     |           |
//   0 +-----------+ 1
Footprint rectangle(double w, double d, double angle_deg = 0.0) {
  return make_footprint({{{0, 0}, {w, 0}, {w, d}, {0, d}}}, angle_deg);
}

// Every edge follows profiles[assign[edge % assign.size()]].
Footprint with_profiles(Footprint fp, std::vector<Profile> profiles, const std::vector<int>& assign) {
  fp.profiles = std::move(profiles);
  std::size_t i = 0;
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) e.profile = assign[i++ % assign.size()];
  return fp;
}

const Profile kWall{"wall", {{0, 0}, {0, 1}}, {"wall"}};
const Profile kHouse{"house", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};

// Volume of a hipped roof at 45 degrees over an a x b rectangle (a >= b): b^2 (3a - b) / 12.
double hip45(double a, double b) { return b * b * (3.0 * a - b) / 12.0; }

// A rectangle A x B whose sides along A move in by ta and those along B by
// tb per unit of height: its volume until it closes (exact by Simpson's rule:
// the area is quadratic in the height) and the height where it closes.
struct Closed {
  double volume, top;
};
Closed shrinking_rectangle(double A, double B, double ta, double tb) {
  const double top = std::min(B / (2 * ta), A / (2 * tb));
  auto area = [&](double z) { return (A - 2 * z * tb) * (B - 2 * z * ta); };
  return {top / 6.0 * (area(0) + 4 * area(top / 2) + area(top)), top};
}

double lowest_z(const Surface& s, const std::string& tag) {
  double z = HUGE_VAL;
  for (const SurfaceFace& f : s.faces)
    if (f.tag == tag)
      for (const auto& loop : f.loops)
        for (auto v : loop) z = std::min(z, s.vertices[v].z);
  return z;
}

TEST(ProfileOffsetRewrite, StepsAtAVertexAndMovesTheRestOut) {
  const Footprint fp = apply_profile_offsets(with_profiles(rectangle(10, 8), {kHouse}, {0}), {{"eaves", 3.0, 0.5, "", {}}});
  ASSERT_EQ(fp.profiles.size(), 1u);  // one rewrite, shared by every edge
  const Profile& p = fp.profiles[0];
  EXPECT_EQ(p.name, "house");
  EXPECT_EQ(p.points, (std::vector<glm::dvec2>{{0, 0}, {0, 3}, {0.5, 3}, {-4.5, 8}}));
  EXPECT_EQ(p.tags, (std::vector<std::string>{"wall", "soffit", "roof"}));
  for (const EdgeSpec& e : fp.loops[0].edges) EXPECT_EQ(e.profile, 0);
}

TEST(ProfileOffsetRewrite, SplitsTheSegmentCrossingTheHeight) {
  const Profile tall{"tall", {{0, 0}, {0, 5}}, {"wall"}};
  const Footprint fp = apply_profile_offsets(with_profiles(rectangle(10, 8), {tall}, {0}), {{"cornice", 2.0, -0.3, "cornice", {}}});
  EXPECT_EQ(fp.profiles[0].points, (std::vector<glm::dvec2>{{0, 0}, {0, 2}, {-0.3, 2}, {-0.3, 5}}));
  EXPECT_EQ(fp.profiles[0].tags, (std::vector<std::string>{"wall", "cornice", "wall"}));
}

TEST(ProfileOffsetRewrite, EdgesWithoutAProfileFollowTheirAngle) {
  const Footprint fp = apply_profile_offsets(rectangle(10, 8, 45.0), {{"o", 1.0, 0.5, "", {}}});
  ASSERT_EQ(fp.profiles.size(), 1u);
  const Profile& p = fp.profiles[0];
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_NEAR(p.points[1].x, -1.0, 1e-12);
  EXPECT_NEAR(p.points[1].y, 1.0, 1e-12);
  EXPECT_NEAR(p.points[2].x, -0.5, 1e-12);
  EXPECT_NEAR(p.points[3].x - p.points[2].x, -(p.points[3].y - p.points[2].y), 1e-12);  // still 45 degrees
  EXPECT_EQ(p.tags, (std::vector<std::string>{"", "soffit", ""}));
}

TEST(ProfileOffsetRewrite, AProfileEndingBelowTheHeightCarriesOnWithItsLastSlope) {
  const Footprint fp = apply_profile_offsets(with_profiles(rectangle(10, 8), {kWall}, {0}), {{"o", 3.0, 0.4, "", {}}});
  const Profile& p = fp.profiles[0];
  EXPECT_EQ(p.points, (std::vector<glm::dvec2>{{0, 0}, {0, 1}, {0, 3}, {0.4, 3}, {0.4, 4}}));
}

TEST(ProfileOffset, HipRoofStartsAtTheEndOfTheSoffit) {
  // Walls to 3 m, a 0.5 m soffit all round, the 45 degree roof from there:
  // a 10 x 8 box and a hipped roof over 11 x 9.
  const Surface s = sweep(apply_profile_offsets(with_profiles(rectangle(10, 8), {kHouse}, {0}), {{"eaves", 3.0, 0.5, "", {}}}));
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 10 * 8 * 3 + hip45(11, 9), 1e-6);
  EXPECT_NEAR(c.max_height, 3.0 + 4.5, 1e-9);
  EXPECT_EQ(faces_per_tag(s), (std::map<std::string, int>{{"roof", 4}, {"soffit", 4}, {"wall", 4}}));
}

TEST(ProfileOffset, BoxWithALedgeAllRound) {
  // Walls capped at 6 m stepping in by 0.5 m at 2 m: 10 x 8 below, 9 x 7 above.
  SweepOptions cap;
  cap.max_height = 6.0;
  const Surface s = sweep(apply_profile_offsets(rectangle(10, 8), {{"setback", 2.0, -0.5, "", {}}}), cap);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 10 * 8 * 2 + 9 * 7 * 4, 1e-6);
  EXPECT_EQ(faces_per_tag(s).at("ledge"), 4);
  for (const SurfaceFace& f : s.faces) {
    if (f.tag != "ledge") continue;
    for (auto v : f.loops[0]) EXPECT_NEAR(s.vertices[v].z, 2.0, 1e-9);
  }
}

TEST(ProfileOffset, OffsetsAtTwoHeightsCompose) {
  // A ledge in at 2 m and a cornice out at 4 m, given highest first.
  SweepOptions cap;
  cap.max_height = 6.0;
  const Surface s = sweep(apply_profile_offsets(rectangle(10, 8), {{"cornice", 4.0, 0.5, "", {}}, {"setback", 2.0, -0.3, "", {}}}), cap);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 10 * 8 * 2 + 9.4 * 7.4 * 2 + 10.4 * 8.4 * 2, 1e-6);
  EXPECT_EQ(faces_per_tag(s).at("ledge"), 4);
  EXPECT_EQ(faces_per_tag(s).at("soffit"), 4);
}

TEST(ProfileOffset, EdgeDistanceOverride) {
  // The right edge (id 1) steps out 1.5 m, the others 0.5 m: 12 x 9 above 2 m.
  SweepOptions cap;
  cap.max_height = 5.0;
  OffsetOverride wide;
  wide.edge_ids = {1};
  wide.distance = 1.5;
  const Surface s = sweep(apply_profile_offsets(rectangle(10, 8), {{"o", 2.0, 0.5, "", {wide}}}), cap);
  const auto c = expect_valid(s);
  EXPECT_NEAR(c.volume, 10 * 8 * 2 + 12 * 9 * 3, 1e-6);
}

// Fig. 5: one offset (a, b) is the shared start of two roofs of different
// gradients; moving it moves both.
TEST(ProfileOffset, TwoGradientsShareOneOffset) {
  const Profile eaves{"eaves", {{0, 0}, {0, 1}}, {"wall"}};
  const Profile hips{"hips", {{0, 0}, {0, 1}}, {"wall"}};
  const Footprint plan = with_profiles(rectangle(12, 8), {eaves, hips}, {0, 1});
  OffsetOverride low, steep;
  low.profile = "eaves";
  low.slope_deg = 30.0;
  steep.profile = "hips";
  steep.slope_deg = 60.0;
  for (const double b : {2.5, 4.0}) {
    SCOPED_TRACE("offset height " + std::to_string(b));
    const double a = 0.6;
    const Surface s = sweep(apply_profile_offsets(plan, {{"roof", b, a, "", {low, steep}}}));
    const auto c = expect_valid(s);
    // Edges 0 and 2 (along x, 12 m) lean in at tan 30, edges 1 and 3 at tan 60.
    const Closed roof = shrinking_rectangle(12 + 2 * a, 8 + 2 * a, std::tan(M_PI / 6), std::tan(M_PI / 3));
    EXPECT_NEAR(c.volume, 12 * 8 * b + roof.volume, 1e-6);
    EXPECT_NEAR(c.max_height, b + roof.top, 1e-9);
    EXPECT_NEAR(lowest_z(s, "soffit"), b, 1e-12);
    EXPECT_EQ(faces_per_tag(s).at("soffit"), 4);
  }
}

// Gable ends drop out of the offset: their walls go straight up into the
// gable, with no step and no soffit, while the eaves overhang.
TEST(ProfileOffset, DroppedEdgesDoNotStep) {
  Profile eaves{"eaves", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};
  Profile gable{"gable", {{0, 0}, {0, 30}}, {"gable"}};
  const Footprint plan = with_profiles(rectangle(12, 8), {eaves, gable}, {0, 1});
  OffsetOverride ends;
  ends.profile = "gable";
  ends.drop = true;
  const Surface s = sweep(apply_profile_offsets(plan, {{"eaves", 3.0, 0.5, "", {ends}}}));
  const auto c = expect_valid(s);
  // A 12 x 8 box to 3 m, then a 45 degree gable roof 9 m wide and 12 m long.
  EXPECT_NEAR(c.volume, 12 * 8 * 3 + 12 * 9 * 9 / 4.0, 1e-6);
  EXPECT_NEAR(c.max_height, 3 + 4.5, 1e-9);
  for (const SurfaceFace& f : s.faces) {
    if (f.source_edge != 1 && f.source_edge != 3) continue;
    EXPECT_EQ(f.tag, "gable");
    for (auto v : f.loops[0]) EXPECT_NEAR(std::abs(s.vertices[v].x - 6.0), 6.0, 1e-9) << "gable wall left its line";
  }
  EXPECT_EQ(faces_per_tag(s).at("soffit"), 2);
}

// An edge that drops out while its profile turns at the offset's height (wall
// to roof) meets its neighbours' soffits vertex to vertex: its wall stays one
// flat rectangle (no fold where the soffit ends) and its roof starts at 3 m.
TEST(ProfileOffset, DroppedEdgeTurningAtTheOffsetHeight) {
  OffsetOverride right;
  right.edge_ids = {1};
  right.drop = true;
  const Surface s = sweep(apply_profile_offsets(with_profiles(rectangle(12, 8), {kHouse}, {0}), {{"eaves", 3.0, 0.5, "", {right}}}));
  const auto c = expect_valid(s);
  // A hipped roof over x in [-0.5, 12], y in [-0.5, 8.5].
  EXPECT_NEAR(c.volume, 12 * 8 * 3 + hip45(12.5, 9), 1e-6);
  EXPECT_EQ(faces_per_tag(s).at("soffit"), 3);
  for (const SurfaceFace& f : s.faces) {
    if (f.source_edge != 1 || f.tag != "wall") continue;
    ASSERT_EQ(f.loops.size(), 1u);
    EXPECT_EQ(f.loops[0].size(), 4u) << "the wall of the dropped edge is not a rectangle";
    for (auto v : f.loops[0]) EXPECT_NEAR(s.vertices[v].x, 12.0, 1e-9);
  }
}

// The offset is defined per profile, never by coordinates: the same edit on
// other footprints (an L, a hexagon with a courtyard) still sweeps to valid solids.
TEST(ProfileOffset, SameOffsetOnOtherFootprints) {
  const ProfileOffset o{"eaves", 3.0, 0.5, "", {}};
  const Footprint l_shape = with_profiles(make_footprint({{{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 9}, {0, 9}}}, 45.0), {kHouse}, {0});
  std::vector<glm::dvec2> hex, hole;
  for (int i = 0; i < 6; ++i) {
    const double t = i * M_PI / 3;
    hex.push_back({12 * std::cos(t), 12 * std::sin(t)});
    hole.push_back({4 * std::cos(-t), 4 * std::sin(-t)});
  }
  const Footprint courtyard = with_profiles(make_footprint({hex, hole}, 45.0), {kHouse}, {0});
  for (const Footprint& fp : {l_shape, courtyard}) {
    const Surface s = sweep(apply_profile_offsets(fp, {o}));
    expect_valid(s);
    EXPECT_NEAR(lowest_z(s, "roof"), 3.0, 1e-9);
  }
}

void expect_refused(const Footprint& fp, const ProfileOffset& o, const std::string& words) {
  try {
    apply_profile_offsets(fp, {o});
    ADD_FAILURE() << "accepted; expected an error with '" << words << "'";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'" + o.name + "'"), std::string::npos) << what;
    EXPECT_NE(what.find(words), std::string::npos) << what;
  }
}

TEST(ProfileOffsetErrors, NameTheOffsetAndWhatIsWrong) {
  const Footprint fp = with_profiles(rectangle(10, 8), {kHouse, kWall}, {0});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_refused(fp, {"nan height", nan, 0.5, "", {}}, "height is not a finite number");
  expect_refused(fp, {"nan distance", 3.0, nan, "", {}}, "distance is not a finite number");
  expect_refused(fp, {"below", -1.0, 0.5, "", {}}, "must be above 0");
  expect_refused(fp, {"at base", 0.0, 0.5, "", {}}, "must be above 0");
  OffsetOverride unknown;
  unknown.profile = "mansard";
  unknown.drop = true;
  expect_refused(fp, {"o1", 3.0, 0.5, "", {unknown}}, "no profile named 'mansard'");
  OffsetOverride unused;  // kWall exists but no edge follows it
  unused.profile = "wall";
  unused.drop = true;
  expect_refused(fp, {"o2", 3.0, 0.5, "", {unused}}, "override 1: no edge follows profile 'wall'");
  OffsetOverride no_edge;
  no_edge.edge_ids = {2, 17};
  no_edge.distance = 1.0;
  expect_refused(fp, {"o3", 3.0, 0.5, "", {no_edge}}, "no edge with id 17");
  OffsetOverride flat;
  flat.edge_ids = {1};
  flat.slope_deg = 90.0;
  expect_refused(fp, {"o4", 3.0, 0.5, "", {flat}}, "slope");
  OffsetOverride idle;
  idle.edge_ids = {1};
  expect_refused(fp, {"o5", 3.0, 0.5, "", {idle}}, "changes nothing");
  OffsetOverride nobody;
  nobody.drop = true;
  expect_refused(fp, {"o6", 3.0, 0.5, "", {nobody}}, "names no profile and no edge");
}

}  // namespace
}  // namespace procex
