// A step that grows the plan until a courtyard's mouth closes: above the step
// the courtyard, enclosed but not covered, is a hole in the cross-section and
// stays open to the sky, with the volume worked out below.
//
// A 12 m square with a keyhole courtyard: a chamber [2, 10]^2 reached through
// a 2 m mouth at the top. Walls rise 3 m, every edge then steps out 1.5 m and
// the roof rises inward at 45 degrees, capped at 3.4 m. The plan is
// rectilinear, so its outward offset by o is its Minkowski sum with a square
// of half-side o: the mouth is closed for o >= 1 and the courtyard is the
// chamber shrunk by o. At t = h - 3 the offset is o = 1.5 - t and the plan's
// area (12 + 2o)^2 - (8 - 2o)^2 = 200 - 80t, so the volume is 3 x 76 (the
// walls) + the integral of 200 - 80t over [0, 0.4] (73.6) = 301.6.
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

TEST(SweepStepCourtyard, AClosedMouthLeavesTheCourtyardAHole) {
  Footprint fp = make_footprint({{{0, 0}, {12, 0}, {12, 12}, {7, 12}, {7, 10}, {10, 10}, {10, 2}, {2, 2}, {2, 10},
                                  {5, 10}, {5, 12}, {0, 12}}},
                                45.0);
  fp.profiles = {{"soffit", {{0, 0}, {0, 3}, {1.5, 3}, {-8.5, 13}}, {"wall", "soffit", "roof"}}};
  for (EdgeSpec& e : fp.loops[0].edges) e.profile = 0;
  SweepOptions options;
  options.max_height = 3.4;
  const Surface s = sweep(fp, options);
  expect_valid(s);
  for (const std::string& line : check_faces_on_planes(fp, options, s, roof_tolerance(fp))) ADD_FAILURE() << line;
  EXPECT_NEAR(surface_volume(s), 301.6, 1e-9 * 301.6);
}

}  // namespace
}  // namespace procex::testing
