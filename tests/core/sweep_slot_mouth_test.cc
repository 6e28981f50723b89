// A slot cut into a 10 m square from its front edge, one of its walls leaning
// out (45 degrees, k = -1) and every other wall vertical, capped at 4 m: the
// leaning wall's corner on the front edge runs along it to the far wall's
// corner, which stands still, and both reach that point at the one height. The
// slot's mouth closes there; what is left of it is a courtyard that the
// leaning wall fills as it rises. The cross-section at height t is the square
// less the slot offset by t at the leaning wall, so the volume is 400 less the
// integral of the slot's area, in closed form below. Were the corners taken to
// pass through each other, the leaning wall would run on into the solid.
#include <cmath>
#include <string>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

constexpr double kHeight = 4.0;

// The slot's right wall (edge 3, from `far` down to (6, 0)) leans out.
Footprint slot_with_leaning_wall(glm::dvec2 far) {
  Footprint fp = make_footprint({{{0, 0}, {4, 0}, {4, 6}, far, {6, 0}, {10, 0}, {10, 10}, {0, 10}}}, 0.0);
  fp.loops[0].edges[3].angle_deg = -45.0;
  return fp;
}

void expect_roof(const Footprint& fp, double volume) {
  SweepOptions options;
  options.max_height = kHeight;
  const Surface s = sweep(fp, options);
  expect_valid(s);
  for (const std::string& line : check_faces_on_planes(fp, options, s, roof_tolerance(fp))) ADD_FAILURE() << line;
  EXPECT_NEAR(surface_volume(s), volume, 1e-9 * volume);
}

TEST(SweepSlotMouth, ALeaningWallClosesTheMouthAtTheFarWallsCorner) {
  // The right wall runs from (7, 6) to (6, 0): at height t its line has moved
  // D / sqrt(37) = t to the left, and the slot is 2 + (y - D) / 6 wide at y,
  // so its area is 15 - D until the mouth closes at D = 12 (the wall through
  // (4, 0)), then (18 - D)^2 / 12 until the courtyard closes at D = 18 (the
  // wall through (4, 6)). Integrated over t = D / sqrt(37): 114 / sqrt(37).
  expect_roof(slot_with_leaning_wall({7, 6}), 100.0 * kHeight - 114.0 / std::sqrt(37.0));
}

TEST(SweepSlotMouth, ANearlyParallelWallClosesTheMouthAtTheFarWallsCorner) {
  // The right wall from (6 + 3e-10, 6) to (6, 0): parallel to the left one
  // up to 5e-11 radians (within the engine's parallel sine, 1e-10), its
  // ray at the meeting just clockwise of the left wall's. The slot, 2 - t
  // wide and 6 deep, closes at t = 2: 12 off the volume (and 1e-9 for the
  // sliver the wall's lean leaves; within the tolerance).
  expect_roof(slot_with_leaning_wall({6.0 + 3e-10, 6}), 100.0 * kHeight - 12.0);
}

TEST(SweepSlotMouth, TwoBlocksLeaningAcrossAStreetMerge) {
  // Two 4 x 6 blocks 2 m apart, their facing walls leaning out at 45 degrees
  // (the right block's parallel to the left's up to 5e-11 radians) and every
  // other wall vertical: the walls meet along their length at t = 1 and the
  // blocks merge into one 10 x 6 block, its cross-section 12 (4 + t) below
  // and 60 above. Volume 54 + 3 x 60 = 234 (passing through each other
  // instead, the blocks would enclose 288).
  Footprint fp = make_footprint({{{0, 0}, {4, 0}, {4, 6}, {0, 6}}, {{6, 0}, {10, 0}, {10, 6}, {6.0 + 3e-10, 6}}}, 0.0);
  fp.loops[0].edges[1].angle_deg = -45.0;
  fp.loops[1].edges[3].angle_deg = -45.0;
  expect_roof(fp, 234.0);
}

}  // namespace
}  // namespace procex::testing
