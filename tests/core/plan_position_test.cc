// The sweep works in a frame centred on the footprint, so that a plan at
// (5e5, 5e6) keeps its digits; its error messages name points of the plan as
// the user has it (core/sweep/plan_position.h), to the clustering distance.
#include <string>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/mesh/surface.h"
#include "core/sweep/plan_position.h"
#include "core/sweep/surface_output.h"

namespace procex::engine {
namespace {

TEST(PlanPosition, NamesThePlansOwnPointToTheClusteringDistance) {
  const PlanPosition at{{5e5, 5e6}, 1e-7};
  EXPECT_EQ(at(glm::dvec2(1.25, -0.5)), "(500001.2500000, 4999999.5000000)");
  EXPECT_EQ(at(glm::dvec3(1.25, -0.5, 3.0)), "(500001.2500000, 4999999.5000000, 3.0000000)");
  // A kilometre-wide plan's clustering distance of 1e-5 m: five decimals.
  EXPECT_EQ((PlanPosition{{0.0, 0.0}, 1e-5})(glm::dvec2(2.0, 3.0)), "(2.00000, 3.00000)");
}

TEST(PlanPosition, WithoutAResolutionSixSignificantDigits) {
  EXPECT_EQ(PlanPosition{}(glm::dvec2(1.5, 2.0)), "(1.5, 2)");
}

// A surface that does not close (one triangle) is refused naming its vertex
// where the plan has it, not where the sweep's frame put it.
TEST(PlanPosition, AnOpenSurfaceIsRefusedAtThePlansOwnPoint) {
  Surface s;
  s.vertices = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
  SurfaceFace f;
  f.loops = {{0, 1, 2}};
  s.faces.push_back(f);
  try {
    close_surface(s, PlanPosition{{5e5, 5e6}, 1e-7});
    FAIL() << "an open surface closed";
  } catch (const SweepError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("(500000.0000000, 5000000.0000000, 0.0000000)"), std::string::npos) << what;
    EXPECT_NE(what.find("(500001.0000000, 5000000.0000000, 0.0000000)"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace procex::engine
