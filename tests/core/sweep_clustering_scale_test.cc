// The clustering scale a sweep reports is the one it used: events closer than
// Surface::tolerance_relative times the plan's extent are one event, and
// events farther apart stay apart. A 10 m rectangle 4e-7 m short of a square
// has a hip roof whose ridge is 4e-7 m long, 4e-8 of its extent: between the
// first scale (1e-8) and the next (1e-7), so at the first its two ends, where
// the short sides vanish at one height, are two vertices; merged into one
// apex, the roof would be a pyramid.
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

TEST(SweepClusteringScale, ARidgeLongerThanTheScaleKeepsItsTwoEnds) {
  constexpr double kRidge = 4e-7;
  const Footprint fp = make_footprint({{{0, 0}, {10, 0}, {10, 10 - kRidge}, {0, 10 - kRidge}}}, 45.0);
  SweepOptions options;
  const Surface s = sweep(fp, options);
  expect_valid(s);
  EXPECT_EQ(s.tolerance_relative, 1e-8);
  EXPECT_EQ(s.retries, 0);
  std::vector<glm::dvec3> top;
  for (const glm::dvec3& v : s.vertices)
    if (v.z > 1.0) top.push_back(v);
  ASSERT_EQ(top.size(), 2u) << "the ridge's ends";
  EXPECT_NEAR(glm::distance(top[0], top[1]), kRidge, 1e-12);
  for (const glm::dvec3& v : top) EXPECT_NEAR(v.z, (10 - kRidge) / 2, 1e-12);
  EXPECT_NEAR(surface_volume(s), volume_of_offset_areas(10 * (10 - kRidge), -2 * (20 - kRidge), 4, (10 - kRidge) / 2),
              1e-12 * 500);
}

}  // namespace
}  // namespace procex::testing
