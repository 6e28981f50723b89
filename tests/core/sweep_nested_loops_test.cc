// A footprint of loops nested four deep: a block with a courtyard, and in the
// courtyard an island building with a courtyard of its own. The base (and
// the cap) of such a plan is one face of two outer loops, and each hole
// belongs to the smallest outer loop around it: the island's courtyard lies
// inside the block's outline too, and given to the block it would leave the
// island's base whole over it (the mutation check's hole_outer survived
// every other test).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

std::vector<glm::dvec2> square(double lo, double hi, bool clockwise) {
  std::vector<glm::dvec2> s{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  if (clockwise) std::swap(s[1], s[3]);
  return s;
}

// The plan area of a face's loop, seen from above (positive counter-clockwise).
double plan_area(const Surface& s, const std::vector<std::uint32_t>& loop) {
  double twice = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const glm::dvec3 a = s.vertices[loop[i]], b = s.vertices[loop[(i + 1) % loop.size()]];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

TEST(SweepNestedLoops, EachHoleBelongsToTheSmallestOuterLoopAroundIt) {
  const Footprint fp = make_footprint(
      {square(0, 40, false), square(8, 32, true), square(14, 26, false), square(18, 22, true)}, 45.0);
  SweepOptions options;
  options.max_height = 1.0;  // below every ridge: the cap has the base's nesting too
  const Surface roof = sweep(fp, options);
  expect_valid(roof);
  for (const std::string& line : check_faces_on_planes(fp, options, roof, roof_tolerance(fp))) ADD_FAILURE() << line;

  // Base and cap: each a face of one outer loop and one hole, the block's
  // (40 - 24 wide ring) and the island's (12 - 4), shrunk by 1 m at the cap.
  std::vector<std::pair<double, double>> base, cap;
  for (const SurfaceFace& f : roof.faces) {
    if (f.kind == FaceKind::Side) continue;
    ASSERT_EQ(f.loops.size(), 2u) << "a base or cap face with " << f.loops.size() << " loops";
    const double outer = std::abs(plan_area(roof, f.loops[0])), hole = std::abs(plan_area(roof, f.loops[1]));
    (f.kind == FaceKind::Base ? base : cap).emplace_back(outer, hole);
  }
  std::sort(base.begin(), base.end());
  std::sort(cap.begin(), cap.end());
  const std::vector<std::pair<double, double>> base_expected{{144, 16}, {1600, 576}};
  const std::vector<std::pair<double, double>> cap_expected{{100, 36}, {1444, 676}};
  ASSERT_EQ(base.size(), 2u);
  ASSERT_EQ(cap.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_NEAR(base[i].first, base_expected[i].first, 1e-9);
    EXPECT_NEAR(base[i].second, base_expected[i].second, 1e-9);
    EXPECT_NEAR(cap[i].first, cap_expected[i].first, 1e-9);
    EXPECT_NEAR(cap[i].second, cap_expected[i].second, 1e-9);
  }
}

}  // namespace
}  // namespace procex::testing
