// Closed-form answers for the sweep engine with one constant angle per edge.
#include "core/sweep/sweep.h"

#include <cmath>

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
