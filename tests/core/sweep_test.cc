// Closed-form answers for the sweep engine with one constant angle per edge.
#include "core/sweep/sweep.h"

#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "tests/core/surface_checks.h"

namespace procex {
namespace {

using testing::check_surface;
using Pts = std::vector<glm::dvec2>;

Pts rect(double x0, double y0, double w, double h) { return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}}; }
Pts reversed(Pts p) { return {p.rbegin(), p.rend()}; }
Pts regular(int n, double r) {
  Pts p;
  for (int k = 0; k < n; ++k) p.push_back({r * std::cos(2 * M_PI * k / n), r * std::sin(2 * M_PI * k / n)});
  return p;
}

testing::SurfaceCheck run(const Footprint& fp, const SweepOptions& o = {}) {
  const Surface s = sweep(fp, o);
  auto r = check_surface(s, 1e-7);
  EXPECT_TRUE(r.closed) << r.problem;
  EXPECT_TRUE(r.planar) << r.problem;
  return r;
}

TEST(Sweep, SquarePyramid) {
  auto r = run(make_footprint({rect(0, 0, 10, 10)}, 45));
  EXPECT_NEAR(r.max_height, 5.0, 1e-9);
  EXPECT_NEAR(r.volume, 100.0 * 5.0 / 3.0, 1e-7);
}

TEST(Sweep, RectangleHipRoof) {
  //  +--------------------+
  //  |\                  /|   ridge at height b/2, volume b^2 (3a - b) / 12
  //  | >----------------< |
  //  |/                  \|
  //  +--------------------+
  auto r = run(make_footprint({rect(0, 0, 20, 10)}, 45));
  EXPECT_NEAR(r.max_height, 5.0, 1e-9);
  EXPECT_NEAR(r.volume, 100.0 * (60.0 - 10.0) / 12.0, 1e-7);
}

TEST(Sweep, GableWithVerticalEnds) {
  Footprint fp = make_footprint({rect(0, 0, 20, 10)}, 45);
  fp.loops[0].edges[1].angle_deg = 0;
  fp.loops[0].edges[3].angle_deg = 0;
  auto r = run(fp);
  EXPECT_NEAR(r.max_height, 5.0, 1e-9);
  EXPECT_NEAR(r.volume, 25.0 * 20.0, 1e-7);
}

TEST(Sweep, SteepLongSidesSetTheRidge) {
  Footprint fp = make_footprint({rect(0, 0, 20, 10)}, 30);
  fp.loops[0].edges[0].angle_deg = 60;
  fp.loops[0].edges[2].angle_deg = 60;
  auto r = run(fp);
  EXPECT_NEAR(r.max_height, 5.0 / std::tan(M_PI / 3), 1e-9);
}

class RegularPolygon : public ::testing::TestWithParam<int> {};

TEST_P(RegularPolygon, ConeHeightAndVolume) {
  const int n = GetParam();
  auto r = run(make_footprint({regular(n, 100.0)}, 45));
  const double apothem = 100.0 * std::cos(M_PI / n);
  const double area = 0.5 * n * 100.0 * 100.0 * std::sin(2 * M_PI / n);
  EXPECT_NEAR(r.max_height, apothem, 1e-7 * 200.0);  // relative to the footprint's size
  EXPECT_NEAR(r.volume, area * apothem / 3.0, 1e-6 * area * apothem);
}
INSTANTIATE_TEST_SUITE_P(Sweep, RegularPolygon, ::testing::Values(3, 5, 8, 16, 64, 256, 1024, 4096));

TEST(Sweep, LShape) {
  //  +----+
  //  |    |
  //  |    +--------+
  //  |             |
  //  +-------------+
  auto r = run(make_footprint({{{0, 0}, {20, 0}, {20, 8}, {9, 8}, {9, 17}, {0, 17}}}, 45));
  EXPECT_NEAR(r.max_height, 4.5, 1e-9);
}

TEST(Sweep, SquareWithSquareHole) {
  auto r = run(make_footprint({rect(0, 0, 10, 10), reversed(rect(3, 3, 4, 4))}, 45));
  EXPECT_NEAR(r.max_height, 1.5, 1e-9);
  EXPECT_NEAR(r.volume, 63.0, 1e-7);
}

// The same ring far from the origin, where a survey plan in UTM lies: its
// volume and flat faces come out as at the origin, up to the last bits of
// coordinates in the millions (relative 1e-16 of 5e6 m).
TEST(Sweep, SquareWithSquareHoleFarFromTheOrigin) {
  const glm::dvec2 far{512345.678, 5012345.678};
  Pts outer = rect(0, 0, 10, 10), hole = reversed(rect(3, 3, 4, 4));
  for (Pts* loop : {&outer, &hole})
    for (glm::dvec2& p : *loop) p += far;
  auto r = run(make_footprint({outer, hole}, 45));
  EXPECT_NEAR(r.max_height, 1.5, 1e-8);
  EXPECT_NEAR(r.volume, 63.0, 1e-6);
}

TEST(Sweep, IslandInsideHole) {
  auto r = run(make_footprint({rect(0, 0, 20, 20), reversed(rect(4, 4, 12, 12)), rect(8, 8, 4, 4)}, 45));
  EXPECT_NEAR(r.max_height, 2.0, 1e-9);
  EXPECT_NEAR(r.volume, 256.0 + 16.0 * 2.0 / 3.0, 1e-7);
}

TEST(Sweep, TwoFootprintsSideBySide) {
  auto r = run(make_footprint({rect(0, 0, 10, 10), rect(12, 0, 10, 10)}, 45));
  EXPECT_NEAR(r.volume, 2 * 100.0 * 5.0 / 3.0, 1e-7);
}

TEST(Sweep, TenCollinearVerticesAlongOneSide) {
  Pts p;
  for (int i = 0; i < 10; ++i) p.push_back({2.0 * i, 0});
  for (glm::dvec2 q : Pts{{20, 0}, {20, 10}, {0, 10}}) p.push_back(q);
  auto r = run(make_footprint({p}, 45));
  EXPECT_NEAR(r.max_height, 5.0, 1e-9);
  EXPECT_NEAR(r.volume, 100.0 * (60.0 - 10.0) / 12.0, 1e-7);
}

TEST(Sweep, MaxHeightCapsWithFlatTop) {
  SweepOptions o;
  o.max_height = 2.0;
  auto r = run(make_footprint({rect(0, 0, 10, 10)}, 45), o);
  EXPECT_NEAR(r.max_height, 2.0, 1e-12);
  EXPECT_NEAR(r.volume, 200.0 - 80.0 + 32.0 / 3.0, 1e-7);
}

TEST(Sweep, VerticalWallsNeedACap) {
  EXPECT_THROW(sweep(make_footprint({rect(0, 0, 10, 10)}, 0)), SweepError);
  SweepOptions o;
  o.max_height = 3.0;
  auto r = run(make_footprint({rect(0, 0, 10, 10)}, 0), o);
  EXPECT_NEAR(r.volume, 300.0, 1e-9);
}

TEST(Sweep, OutwardLeaningWallsWithCap) {
  SweepOptions o;
  o.max_height = 2.0;
  auto r = run(make_footprint({rect(0, 0, 10, 10)}, -20), o);
  const double t = std::tan(20 * M_PI / 180);
  // integral over z in [0, 2] of (10 + 2 z t)^2
  const double expected = 200.0 + 2.0 * 10.0 * t * 4.0 + 4.0 * t * t * 8.0 / 3.0;
  EXPECT_NEAR(r.volume, expected, 1e-7);
}

}  // namespace
}  // namespace procex

namespace procex {
namespace {

Footprint with_profile(const std::vector<glm::dvec2>& pts, Profile profile) {
  Footprint fp = make_footprint({pts}, 45);
  fp.profiles.push_back(std::move(profile));
  for (auto& e : fp.loops[0].edges) e.profile = 0;
  return fp;
}

std::map<std::string, int> faces_per_tag(const Surface& s) {
  std::map<std::string, int> n;
  for (const auto& f : s.faces)
    if (f.kind == FaceKind::Side) ++n[f.tag];
  return n;
}

TEST(SweepProfiles, ConstantProfileEqualsConstantAngle) {
  for (double angle : {30.0, 45.0, 60.0}) {
    const Surface a = sweep(make_footprint({{{0, 0}, {20, 0}, {20, 8}, {9, 8}, {9, 17}, {0, 17}}}, angle));
    const Surface b = sweep(with_profile({{0, 0}, {20, 0}, {20, 8}, {9, 8}, {9, 17}, {0, 17}},
                                         Profile::straight(angle, 100.0, "roof")));
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    for (std::size_t i = 0; i < a.vertices.size(); ++i) EXPECT_EQ(a.vertices[i], b.vertices[i]);
    ASSERT_EQ(a.faces.size(), b.faces.size());
    for (std::size_t i = 0; i < a.faces.size(); ++i) EXPECT_EQ(a.faces[i].loops, b.faces[i].loops);
  }
}

TEST(SweepProfiles, WallsThenHipRoof) {
  //   roof  /\      ridge at 3 + 5 = 8
  //   wall |  |     walls 3 high, then 45 degrees
  const Profile house{"house", {{0, 0}, {0, 3}, {-10, 13}}, {"wall", "roof"}};
  const Surface s = sweep(with_profile({{0, 0}, {20, 0}, {20, 10}, {0, 10}}, house));
  const auto r = testing::check_surface(s, 1e-7);
  EXPECT_TRUE(r.closed) << r.problem;
  EXPECT_TRUE(r.planar) << r.problem;
  EXPECT_NEAR(r.max_height, 8.0, 1e-9);
  EXPECT_NEAR(r.volume, 200.0 * 3.0 + 100.0 * (60.0 - 10.0) / 12.0, 1e-7);
  const std::map<std::string, int> expected{{"roof", 4}, {"wall", 4}};
  EXPECT_EQ(faces_per_tag(s), expected);
}

TEST(SweepProfiles, Mansard) {
  // Walls to 3, a steep lower roof leaning in 1 over 3, a shallow upper roof leaning in 3 per 1.
  const Profile mansard{"mansard", {{0, 0}, {0, 3}, {-1, 6}, {-4, 7}}, {"wall", "mansard", "roof"}};
  const Surface s = sweep(with_profile({{0, 0}, {20, 0}, {20, 10}, {0, 10}}, mansard));
  const auto r = testing::check_surface(s, 1e-7);
  EXPECT_TRUE(r.closed) << r.problem;
  EXPECT_TRUE(r.planar) << r.problem;
  // The 18 x 8 rectangle left at height 6 closes 8 / 2 / 3 higher.
  EXPECT_NEAR(r.max_height, 6.0 + 4.0 / 3.0, 1e-9);
  double lower = 0.0;  // integral of (20 - 2t/3)(10 - 2t/3) over t in [0, 3]
  for (int i = 0; i < 30000; ++i) {
    const double t = (i + 0.5) * 3.0 / 30000;
    lower += (20 - 2 * t / 3) * (10 - 2 * t / 3) * 3.0 / 30000;
  }
  const double upper = (1.0 / 3.0) * 64.0 * (54.0 - 8.0) / 12.0;  // hip roof on 18 x 8, slope 3
  EXPECT_NEAR(r.volume, 600.0 + lower + upper, 1e-6);
  const std::map<std::string, int> expected{{"mansard", 4}, {"roof", 4}, {"wall", 4}};
  EXPECT_EQ(faces_per_tag(s), expected);
}

TEST(SweepProfiles, GambrelOnTheLongSidesGablesOnTheEnds) {
  Footprint fp = make_footprint({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}, 0);
  fp.profiles.push_back({"gambrel", {{0, 0}, {0, 3}, {-2, 5}, {-5, 7}}, {"wall", "lower", "upper"}});
  fp.profiles.push_back({"gable end", {{0, 0}, {0, 20}}, {"wall"}});
  for (int e : {0, 2}) fp.loops[0].edges[e].profile = 0;
  for (int e : {1, 3}) fp.loops[0].edges[e].profile = 1;
  const Surface s = sweep(fp);
  const auto r = testing::check_surface(s, 1e-7);
  EXPECT_TRUE(r.closed) << r.problem;
  EXPECT_TRUE(r.planar) << r.problem;
  // Cross-section: 10 wide; 2 in at height 5, then 1.5 in per unit height: the
  // 6 left close 3 / 1.5 = 2 higher.
  EXPECT_NEAR(r.max_height, 7.0, 1e-9);
  const double section = 10.0 * 3.0 + (10.0 + 6.0) / 2.0 * 2.0 + 6.0 * 2.0 / 2.0;
  EXPECT_NEAR(r.volume, section * 20.0, 1e-6);
}

TEST(SweepProfiles, BadProfilesAreRefusedWithTheirNames) {
  Profile down{"sags", {{0, 0}, {0, 3}, {-1, 2}}, {"wall", "roof"}};
  try {
    sweep(with_profile({{0, 0}, {20, 0}, {20, 10}, {0, 10}}, down));
    FAIL() << "a descending profile was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'sags'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("segment 1"), std::string::npos) << e.what();
  }
  EXPECT_THROW(sweep(with_profile({{0, 0}, {20, 0}, {20, 10}, {0, 10}}, Profile{"empty", {}, {}})), InputError);
  EXPECT_THROW(sweep(with_profile({{0, 0}, {20, 0}, {20, 10}, {0, 10}},
                                  Profile{"nan", {{0, 0}, {std::nan(""), 3}}, {"wall"}})),
               InputError);
}

}  // namespace
}  // namespace procex

namespace procex {
namespace {

TEST(Sweep, TwoFootprintsGrowIntoEachOther) {
  // Two 10 x 10 squares 2 apart, walls leaning out at 45 degrees: they touch
  // at height 1 and grow on as one solid until the cap at 3.
  SweepOptions o;
  o.max_height = 3.0;
  const Surface s = sweep(make_footprint({rect(0, 0, 10, 10), rect(12, 0, 10, 10)}, -45), o);
  const auto r = testing::check_surface(s, 1e-7);
  EXPECT_TRUE(r.closed) << r.problem;
  EXPECT_TRUE(r.planar) << r.problem;
  double volume = 0.0;  // each square is (10 + 2z)^2; past z = 1 they overlap by (2z - 2) x (10 + 2z)
  const int steps = 300000;
  for (int i = 0; i < steps; ++i) {
    const double z = (i + 0.5) * 3.0 / steps;
    const double side = 10 + 2 * z;
    volume += (2 * side * side - (z > 1 ? (2 * z - 2) * side : 0.0)) * 3.0 / steps;
  }
  EXPECT_NEAR(r.volume, volume, 1e-6 * volume);
  int caps = 0;
  for (const auto& f : s.faces) caps += f.kind == FaceKind::Cap;
  EXPECT_EQ(caps, 1) << "the two footprints end as one solid under one cap";
}

TEST(Sweep, VolumeMinimisingResolvesTheOtherWay) {
  // Collinear neighbours at 30 and 60 degrees: maximising keeps the wall that
  // leans in less (30), minimising the one that leans in more (60).
  Footprint fp = make_footprint({{{0, 0}, {10, 0}, {20, 0}, {20, 10}, {0, 10}}}, 45);
  fp.loops[0].edges[0].angle_deg = 30;
  fp.loops[0].edges[1].angle_deg = 60;
  SweepOptions max_o, min_o;
  min_o.ambiguity = Ambiguity::MinimizeVolume;
  const auto rmax = testing::check_surface(sweep(fp, max_o), 1e-7);
  const auto rmin = testing::check_surface(sweep(fp, min_o), 1e-7);
  EXPECT_TRUE(rmax.closed && rmin.closed) << rmax.problem << rmin.problem;
  Footprint as30 = fp, as60 = fp;
  as30.loops[0].edges[1].angle_deg = 30;
  as60.loops[0].edges[0].angle_deg = 60;
  EXPECT_NEAR(rmax.volume, testing::check_surface(sweep(as30), 1e-7).volume, 1e-9);
  EXPECT_NEAR(rmin.volume, testing::check_surface(sweep(as60), 1e-7).volume, 1e-9);
  EXPECT_GT(rmax.volume, rmin.volume);
}

TEST(Sweep, NeighboursBentByMoreThanRoundingFollowTheWayTheirLinesCross) {
  // The same neighbours at 30 and 60 degrees, the second turned by 2e-7 rad:
  // their corner runs along the line at 5.8e6 m per m, too fast to follow,
  // into the first edge where the turn is convex (60 runs on over it) and
  // into the second where it is reflex (30 runs on), whatever the volume rule.
  for (const double bend : {2e-6, -2e-6}) {
    Footprint fp = make_footprint({{{0, 0}, {10, 0}, {20, bend}, {20, 10}, {0, 10}}}, 45);
    fp.loops[0].edges[0].angle_deg = 30;
    fp.loops[0].edges[1].angle_deg = 60;
    Footprint kept = fp;
    if (bend > 0.0)
      kept.loops[0].edges[0].angle_deg = 60;
    else
      kept.loops[0].edges[1].angle_deg = 30;
    for (const Ambiguity rule : {Ambiguity::MaximizeVolume, Ambiguity::MinimizeVolume}) {
      SweepOptions o;
      o.ambiguity = rule;
      const auto r = testing::check_surface(sweep(fp, o), 1e-7);
      EXPECT_TRUE(r.closed) << bend << ": " << r.problem;
      EXPECT_NEAR(r.volume, testing::check_surface(sweep(kept, o), 1e-7).volume, 1e-4) << bend;
    }
  }
}

TEST(Sweep, APlanTooThinEverywhereSaysSo) {
  // A triangle 8e-7 m thin and 9 m long: every event falls within the
  // clustering distance of its base, and the roof would come out flat.
  Footprint fp = make_footprint({{{82.1377, 38.895}, {84.5968, 43.1278}, {86.6817, 46.7165}}}, 45);
  fp.loops[0].edges[0].angle_deg = 0;
  fp.loops[0].edges[1].angle_deg = 72;
  fp.loops[0].edges[2].angle_deg = 30;
  SweepOptions o;
  o.max_height = 3.0;
  try {
    (void)sweep(fp, o);
    FAIL() << "a flat roof was returned";
  } catch (const SweepError& e) {
    EXPECT_NE(std::string(e.what()).find("the roof has no height"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace procex
