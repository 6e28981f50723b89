// LOD0 and LOD1 of a building (core/mesh/level_of_detail.h) against closed
// forms: a hipped roof's volume, and a courtyard's footprint area.
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/level_of_detail.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "tests/support/plan_of_mesh.h"

namespace procex {
namespace {

Mesh building(const std::vector<std::vector<glm::dvec2>>& loops, double angle_deg) {
  return build_mesh(sweep(make_footprint(loops, angle_deg)));
}

using test::Plan;
using test::plan_of;

// A 20 x 10 rectangle, every edge at 45 degrees: a hipped roof of volume
// a^2 (3b - a) / 12 = 100 * 50 / 12 (a gabled prism a^2/4 * (b - a) plus a
// pyramid a^3/6), so its mean height is that over the area 200.
TEST(LevelOfDetail, HippedRoofsMeanHeightIsItsVolumeOverItsFootprint) {
  const Mesh roof = building({{{0, 0}, {20, 0}, {20, 10}, {0, 10}}}, 45);
  const double volume = 100.0 * 50.0 / 12.0;
  EXPECT_NEAR(validate(roof).volume, volume, 1e-9);
  EXPECT_NEAR(mean_height(roof), volume / 200.0, 1e-9);

  const Mesh block = mean_height_block(roof);
  const ValidationReport v = validate(block);
  EXPECT_TRUE(v.ok()) << ::testing::PrintToString(v.problems);
  EXPECT_NEAR(v.volume, volume, 1e-9);
  const Plan p = plan_of(block);
  EXPECT_NEAR(p.low, 0.0, 1e-12);
  EXPECT_NEAR(p.high, volume / 200.0, 1e-12);
  EXPECT_NEAR(p.up_area, 200.0, 1e-9);  // the flat top
  EXPECT_NEAR(p.down_area, 200.0, 1e-9);

  const Mesh footprint = footprint_mesh(roof);
  const Plan f = plan_of(footprint);
  EXPECT_NEAR(f.up_area, 200.0, 1e-9);  // seen from above
  EXPECT_EQ(f.down_area, 0.0);
  EXPECT_EQ(f.low, 0.0);
  EXPECT_EQ(f.high, 0.0);
}

// A 30 x 30 square round a 10 x 10 courtyard: the block keeps the courtyard
// (walls on both rings), so its volume is still the building's.
TEST(LevelOfDetail, ACourtyardStaysOpenInTheBlockAndTheFootprint) {
  const Mesh ring = building({{{0, 0}, {30, 0}, {30, 30}, {0, 30}}, {{10, 10}, {10, 20}, {20, 20}, {20, 10}}}, 45);
  const double volume = validate(ring).volume;
  ASSERT_GT(volume, 0.0);
  EXPECT_NEAR(mean_height(ring), volume / 800.0, 1e-9);
  const Mesh block = mean_height_block(ring);
  const ValidationReport v = validate(block);
  EXPECT_TRUE(v.ok()) << ::testing::PrintToString(v.problems);
  EXPECT_NEAR(v.volume, volume, 1e-9 * volume);
  EXPECT_NEAR(plan_of(footprint_mesh(ring)).up_area, 800.0, 1e-9);
}

TEST(LevelOfDetail, AMeshWithoutAFootprintHasNoCoarserLevels) {
  Mesh none;
  add_face_properties(none);
  EXPECT_EQ(mean_height(none), 0.0);
  EXPECT_EQ(mean_height_block(none).n_faces(), 0u);
  EXPECT_EQ(footprint_mesh(none).n_faces(), 0u);
}

}  // namespace
}  // namespace procex
