// The clustering scale a sweep reports is the one it used: events closer than
// Surface::tolerance_relative times the plan's extent are one event, and
// events farther apart stay apart. A 10 m rectangle 4e-7 m short of a square
// has a hip roof whose ridge is 4e-7 m long, 4e-8 of its extent: between the
// first scale (1e-8) and the next (1e-7), so at the first its two ends, where
// the short sides vanish at one height, are two vertices; merged into one
// apex, the roof would be a pyramid.
//
// But events rounding alone put apart are one: where an edge's neighbours
// are nearly parallel to it, rounding moves their meeting by far more than
// the clustering scale (SweepTolerances::meeting_slack).
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
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

// A regular polygon of 163,840 sides, 100 m in radius, its corners rounded
// to doubles: the height where an edge's neighbours squeeze it out moves by
// about 2 e / t^2 for a line moved by e (t = 2 pi / n, the turn between
// edges), so rounding spread the edge events over several times the
// clustering distance round the centre, and the sweep left 16 apexes within
// 1.3e-5 m there, each a fan of thousands of triangles (at 262,144 sides 39
// within 3.5e-5 m, whose validation then tested every pair of triangles:
// every box, widened by the validator's tolerance, held the whole cluster).
// Each event is known only to within its planes' conditioning times the
// rounding, so they are one: one apex, on the centre at the height where the
// polygon's planes meet, and the validator's work round it stays a few pairs
// a face.
TEST(SweepClusteringScale, EdgeEventsSpreadByRoundingAloneAreOneApex) {
  constexpr int kSides = 163840;
  std::vector<glm::dvec2> ring;
  for (int k = 0; k < kSides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kSides;
    ring.push_back({100.0 * std::cos(a), 100.0 * std::sin(a)});
  }
  const Surface s = sweep(make_footprint({ring}, 45.0));
  EXPECT_EQ(s.tolerance_relative, 1e-8);
  std::vector<glm::dvec3> top;
  for (const glm::dvec3& v : s.vertices)
    if (v.z > 1.0) top.push_back(v);
  ASSERT_EQ(top.size(), 1u) << "apexes";
  EXPECT_NEAR(glm::length(glm::dvec2(top[0])), 0.0, 1e-9);
  EXPECT_NEAR(top[0].z, 100.0 * std::cos(std::numbers::pi / kSides), 1e-9);
  const ValidationReport v = validate(build_mesh(s), {.search_proven_pairs = true});
  EXPECT_TRUE(v.ok()) << (v.problems.empty() ? std::string() : v.problems.front());
  EXPECT_LT(v.triangle_pairs_tested, 64u * kSides);
}

}  // namespace
}  // namespace procex::testing
