// Two blocks that come to touch at one point and part again (generated angles
// finding 13108, built in code). Block B, x in [0, 4], has a standing west
// wall and a south edge leaning in at 45 degrees; block A, west of it, has an
// east edge leaning out at 45 degrees and a north edge leaning out at 30. A's
// north edge (y = 0) starts 1 m north of the line of B's south edge, which
// moves north faster (1 m per m against tan 30), so the two lines coincide
// at T = 1 / (1 - tan 30), when A's north-east corner reaches x = 0: the
// corners of both blocks meet there. Above T, A's north edge runs on below B's south-west
// corner, which climbs B's west wall faster than A's north edge crosses it:
// the gap between B's west wall and A's north edge never closes and the blocks
// only touched. Merged there (the gap taken to close along B's west wall),
// the one loop crosses itself: one cap, and 0.14 m3 more than the blocks.
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

double loop_area(const Surface& s, const std::vector<std::uint32_t>& loop) {
  double twice = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const glm::dvec3& p = s.vertices[loop[i]];
    const glm::dvec3& q = s.vertices[loop[(i + 1) % loop.size()]];
    twice += p.x * q.y - q.x * p.y;
  }
  return 0.5 * twice;
}

TEST(SweepTouchingLoops, ALeaningOutEdgeBehindAFasterCollinearCornerLeavesTwoLoops) {
  const double k = std::tan(M_PI / 6.0);
  const double touch = 1.0 / (1.0 - k);
  const double height = touch + 1.0;
  Footprint fp = make_footprint({{{-6, -4}, {-touch, -4}, {-touch, 0}, {-6, 0}},  // A
                                 {{0, -1}, {4, -1}, {4, 3}, {0, 3}}},              // B
                                0.0);
  fp.loops[0].edges[1].angle_deg = -45.0;
  fp.loops[0].edges[2].angle_deg = -30.0;
  fp.loops[1].edges[0].angle_deg = 45.0;
  SweepOptions options;
  options.max_height = height;
  const Surface s = sweep(fp, options);
  expect_valid(s);
  for (const std::string& line : check_faces_on_planes(fp, options, s, roof_tolerance(fp))) ADD_FAILURE() << line;

  // A's cross-section at t is (6 - T + t) by (4 + k t), B's 4 by (4 - t).
  const double a_at = (6.0 - touch + height) * (4.0 + k * height);
  const double b_at = 4.0 * (4.0 - height);
  const double volume = volume_of_offset_areas(4.0 * (6.0 - touch), 4.0 + k * (6.0 - touch), k, height) +
                        volume_of_offset_areas(16.0, -4.0, 0.0, height);
  EXPECT_NEAR(surface_volume(s), volume, 1e-9 * volume);
  std::vector<double> caps;
  for (const SurfaceFace& f : s.faces)
    if (f.kind == FaceKind::Cap)
      for (const auto& loop : f.loops) caps.push_back(loop_area(s, loop));
  ASSERT_EQ(caps.size(), 2u) << "one cap per block";
  if (caps[0] > caps[1]) std::swap(caps[0], caps[1]);
  EXPECT_NEAR(caps[0], b_at, 1e-9 * a_at);
  EXPECT_NEAR(caps[1], a_at, 1e-9 * a_at);
}

}  // namespace
}  // namespace procex::testing
