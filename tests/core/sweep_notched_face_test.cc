// A face whose plane two merging blocks fill in a triangle whose tip is on the
// face's own boundary (generated angles finding 75421, built in code). Block
// M (x in [-5, 0], y in [-1, 4]: its south roof reaches S's south wall's line
// only at 2 m, after S has gone, so no edges of different angles run on from
// each other there) and block S (x in [1, 3], y in [1, 2]) lean out towards
// each other at 0.6 m per m for their first metre, then roof back at 0.9 m
// per m; the other edges are roofs at 45 degrees but for S's south wall,
// which stands. The leaning walls meet at 5/6 m along S's west edge, and the
// blocks merge there. Above, M's east face is cut by a triangle both blocks
// fill: between S's corner on its standing south wall and its corner on its
// north roof, which reaches that wall at 1 m, where M's east face ends and
// its roof begins. So the face has a notch whose tip is on its top edge: a
// hole of the face that touches its outer loop at one vertex. The mesh must
// close and validate, and the solid is the union of the blocks: their
// volumes, each swept alone, less their overlap, which is in closed form.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

// The lean profile's first two segments, from the ground: 0.6 out over the
// first metre, then 3.6 in over the next four.
Profile lean() { return {"lean", {{0, 0}, {0.6, 1}, {-3, 5}}, {"overhang", "roof"}}; }

Footprint blocks(bool with_m, bool with_s) {
  std::vector<std::vector<glm::dvec2>> loops;
  if (with_m) loops.push_back({{-5, -1}, {0, -1}, {0, 4}, {-5, 4}});
  if (with_s) loops.push_back({{1, 1}, {3, 1}, {3, 2}, {1, 2}});
  Footprint fp = make_footprint(loops, 45.0);
  fp.profiles = {lean()};
  if (with_m) fp.loops[0].edges[1].profile = 0;
  if (with_s) {
    Loop& s = fp.loops.back();
    s.edges[0].angle_deg = 0.0;
    s.edges[3].profile = 0;
  }
  return fp;
}

double swept_volume(const Footprint& fp) {
  const Surface s = sweep(fp, {});
  expect_valid(s);
  for (const std::string& line : check_faces_on_planes(fp, {}, s, roof_tolerance(fp))) ADD_FAILURE() << line;
  return surface_volume(s);
}

TEST(SweepNotchedFace, ANotchWhoseTipIsOnTheFacesBoundaryClosesTheSurface) {
  const Footprint both = blocks(true, true);
  const Surface s = sweep(both, {});
  int holes = 0;
  for (const SurfaceFace& f : s.faces) holes += static_cast<int>(f.loops.size()) - 1;
  EXPECT_EQ(holes, 1) << "M's east face, with the notch";
  // The walls overlap from 5/6 m: 1.2 z - 1 wide across S's north roof's
  // 1 - z, up to 1 m: the integral is 1 / 1080.
  const double volume = swept_volume(blocks(true, false)) + swept_volume(blocks(false, true)) - 1.0 / 1080.0;
  EXPECT_NEAR(swept_volume(both), volume, 1e-9 * volume);
}

}  // namespace
}  // namespace procex::testing
