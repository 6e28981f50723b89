// Plans drawn on a grid, where many events fall at exactly one point and
// height (reflex corners meeting head-on, three or more ridges at one point,
// collinear vertices, parallel edges at equal distances, symmetric holes):
// the generalized intersection event (paper 4.2) must resolve them all. Each
// roof validates, its ridges are where the closed form puts them, and a copy
// far from the origin or at another size gives the same roof, transformed.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/prepare.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"

namespace procex {
namespace {

using Pts = std::vector<glm::dvec2>;

struct Plan {
  std::string name;
  std::vector<Pts> loops;
  double half_width;  // half the narrowest wing: the ridges' plan distance from the eaves
  double volume_45 = 0.0;  // at 45 degrees, where a closed form gives it (0: none)
};

Pts comb(int teeth) {
  // A 1 m deep spine along y = 0..1 with teeth 1 m wide and 2 m long, 1 m apart.
  const double right = 2.0 * teeth - 1.0;
  Pts p{{0, 0}, {right, 0}};
  for (int i = 0; i < teeth; ++i) {
    const double x = right - 2.0 * i;
    p.push_back({x, 3});
    p.push_back({x - 1, 3});
    if (i + 1 < teeth) {
      p.push_back({x - 1, 1});
      p.push_back({x - 2, 1});
    }
  }
  return p;
}

std::vector<Plan> plans() {
  std::vector<Plan> out;
  out.push_back({"T", {{{0, 0}, {24, 0}, {24, 8}, {16, 8}, {16, 20}, {8, 20}, {8, 8}, {0, 8}}}, 4.0});
  out.push_back({"H",
                 {{{0, 0}, {8, 0}, {8, 8}, {16, 8}, {16, 0}, {24, 0}, {24, 24}, {16, 24}, {16, 16}, {8, 16}, {8, 24},
                   {0, 24}}},
                 4.0});
  out.push_back({"Comb", {comb(5)}, 0.5});
  Plan holes{"SquareWithFourHoles", {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}}, 1.0};
  for (glm::dvec2 c : {glm::dvec2{2, 2}, glm::dvec2{6, 2}, glm::dvec2{2, 6}, glm::dvec2{6, 6}})
    holes.loops.push_back({c, c + glm::dvec2{0, 2}, c + glm::dvec2{2, 2}, c + glm::dvec2{2, 0}});
  out.push_back(holes);
  // A hip roof, a = 8 by b = 2: volume b^2 (3a - b) / 12 at 45 degrees.
  out.push_back({"RectangleWithCollinearVertices",
                 {{{0, 0}, {1, 0}, {4, 0}, {7, 0}, {8, 0}, {8, 1}, {8, 2}, {7, 2}, {4, 2}, {1, 2}, {0, 2}, {0, 1}}},
                 1.0,
                 4.0 * 22.0 / 12.0});
  return out;
}

Footprint transformed(const Plan& plan, double angle, double scale, glm::dvec2 offset) {
  std::vector<Pts> loops = plan.loops;
  for (Pts& loop : loops)
    for (glm::dvec2& p : loop) p = p * scale + offset;
  return make_footprint(loops, angle);
}

struct Roof {
  Surface surface;
  ValidationReport report;
};

Roof roof(const Footprint& fp) {
  const PreparedFootprint prepared = prepare_footprint(fp);
  Roof r{sweep(prepared.footprint), {}};
  r.report = validate(build_mesh(r.surface));
  return r;
}

std::string problems(const ValidationReport& v) {
  std::string s;
  for (const std::string& p : v.problems) s += p + "; ";
  return s;
}

double top(const Surface& s) {
  double z = 0.0;
  for (const glm::dvec3& v : s.vertices) z = std::max(z, v.z);
  return z;
}

struct ExactCase {
  Plan plan;
  double angle;
};

void PrintTo(const ExactCase& c, std::ostream* os) { *os << c.plan.name << " at " << c.angle << " degrees"; }

class ExactPlan : public ::testing::TestWithParam<ExactCase> {};

TEST_P(ExactPlan, ValidatesWithRidgesAtTheClosedFormHeight) {
  const ExactCase& c = GetParam();
  const Roof r = roof(transformed(c.plan, c.angle, 1.0, {0.0, 0.0}));
  EXPECT_TRUE(r.report.ok()) << problems(r.report);
  const double k = std::tan(c.angle * M_PI / 180.0);
  EXPECT_NEAR(top(r.surface), c.plan.half_width / k, 1e-9 * c.plan.half_width / k);
  if (c.plan.volume_45 > 0.0) {
    EXPECT_NEAR(r.report.volume, c.plan.volume_45 / k, 1e-9 * c.plan.volume_45 / k);
  }
}

// The same plan far from the origin and at other sizes: the same roof, moved
// and scaled (the same vertices, to within the coordinates' own precision,
// and the same faces and volume). Sizes are tried at the origin: a 1 mm plan
// at 1e9 m has no exact corners left (coordinates there are 1.2e-7 m apart).
TEST_P(ExactPlan, SameRoofAnywhereAndAtAnySize) {
  const ExactCase& c = GetParam();
  const Roof home = roof(transformed(c.plan, c.angle, 1.0, {0.0, 0.0}));
  ASSERT_TRUE(home.report.ok()) << problems(home.report);
  struct Copy {
    double scale;
    glm::dvec2 offset;
  };
  for (const Copy copy : {Copy{1.0, {5e5, 5e6}}, Copy{1.0, {1e9, -1e9}}, Copy{1.0, {-1e9, 1e9}}, Copy{1e-3, {0.0, 0.0}},
                          Copy{1e3, {0.0, 0.0}}, Copy{1e4, {0.0, 0.0}}}) {
    SCOPED_TRACE("scale " + std::to_string(copy.scale) + ", offset " + std::to_string(copy.offset.x));
    const Roof moved = roof(transformed(c.plan, c.angle, copy.scale, copy.offset));
    EXPECT_TRUE(moved.report.ok()) << problems(moved.report);
    EXPECT_EQ(moved.surface.faces.size(), home.surface.faces.size());
    EXPECT_NEAR(moved.report.volume, home.report.volume * std::pow(copy.scale, 3),
                1e-9 * home.report.volume * std::pow(copy.scale, 3));
    ASSERT_EQ(moved.surface.vertices.size(), home.surface.vertices.size());
    // Coordinates near 1e9 carry about 1e-7 of absolute precision.
    const double precision =
        1e-9 * copy.scale + 4e-16 * std::max(std::abs(copy.offset.x), std::abs(copy.offset.y));
    for (const glm::dvec3& h : home.surface.vertices) {
      const glm::dvec3 want{glm::dvec2(h) * copy.scale + copy.offset, h.z * copy.scale};
      const bool found = std::any_of(moved.surface.vertices.begin(), moved.surface.vertices.end(),
                                     [&](const glm::dvec3& got) {
                                       return std::abs(got.x - want.x) <= precision &&
                                              std::abs(got.y - want.y) <= precision &&
                                              std::abs(got.z - want.z) <= 1e-9 * copy.scale;
                                     });
      EXPECT_TRUE(found) << "no vertex at (" << want.x << ", " << want.y << ", " << want.z << ")";
    }
  }
}

std::vector<ExactCase> cases() {
  std::vector<ExactCase> out;
  for (const Plan& p : plans())
    for (double angle : {30.0, 45.0, 60.0}) out.push_back({p, angle});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Sweep, ExactPlan, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<ExactCase>& info) {
                           return info.param.plan.name + "_" + std::to_string(static_cast<int>(info.param.angle));
                         });

}  // namespace
}  // namespace procex
