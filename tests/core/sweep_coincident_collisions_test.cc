// Collisions that coincide without sharing a corner: the four reflex corners
// of a plus meet at its centre at one height, each with the arm walls across
// from it. Turned and moved, their computed meetings differ in the last bits,
// and the roof must come out the same: valid, every face on its edge's plane,
// heights those of the planes seen from each point, and the volume of the
// offset areas. Offset inward by t, the plus of arms 2 wide reaching 3 from
// its centre is a plus of half-width w = 1 - t reaching 3 - t, of area
// 4 w^2 + 16 w: 28 / 3 integrated over t in [0, 1].
#include <cmath>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

TEST(SweepCoincidentCollisions, APlusRoofsAlikeTurnedAndMoved) {
  const std::vector<glm::dvec2> plus{{1, -1}, {3, -1}, {3, 1},   {1, 1},   {1, 3},   {-1, 3},
                                     {-1, 1}, {-3, 1}, {-3, -1}, {-1, -1}, {-1, -3}, {1, -3}};
  for (double degrees : {0.0, 10.0, 30.0, 45.0, 77.0})
    for (glm::dvec2 at : {glm::dvec2(0, 0), glm::dvec2(1000.3, 2000.7), glm::dvec2(-37.1, 12.9)}) {
      SCOPED_TRACE("turned " + std::to_string(degrees) + " degrees, moved to (" + std::to_string(at.x) + ", " +
                   std::to_string(at.y) + ")");
      const double c = std::cos(degrees * M_PI / 180.0), s = std::sin(degrees * M_PI / 180.0);
      std::vector<glm::dvec2> loop;
      for (glm::dvec2 p : plus) loop.push_back(at + glm::dvec2(c * p.x - s * p.y, s * p.x + c * p.y));
      const Footprint fp = make_footprint({loop}, 45.0);
      const SweepOptions options;
      const Surface roof = sweep(fp, options);
      expect_valid(roof);
      const double tol = roof_tolerance(fp);
      for (const std::string& line : check_faces_on_planes(fp, options, roof, tol)) ADD_FAILURE() << line;
      for (const std::string& line : check_inward_roof(fp, options, roof, tol, 7)) ADD_FAILURE() << line;
      EXPECT_NEAR(surface_volume(roof), 28.0 / 3.0, 1e-9);
    }
}

}  // namespace
}  // namespace procex::testing
