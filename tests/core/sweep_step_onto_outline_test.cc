// A courtyard's ledge that steps onto the outline's line beside the
// outline's own step out: above the steps the building's new side strip and
// the block below it touch along one edge, joined round both its ends
// through the strips at either side. The edge then carries two faces each
// way (the outline's wall and the courtyard's ledge below, the outline's
// soffit and the courtyard's new wall above), and the mesh must still be a
// 2-manifold: each pair gets its own edge (angles seed 1746 was refused by
// OpenMesh as a third face at one edge).
//
// A 12 m square around a courtyard [2, 10]^2. Every wall rises straight to
// 5 m, but at 3 m the outline's east edge (x = 12) steps out 1.5 m and the
// courtyard's east edge (x = 10) steps 2 m into the block, onto x = 12.
// Below 3 m the plan is the ring, 144 - 64 = 80 m^2; above it the block
// [0, 13.5] x [0, 12] around the courtyard [2, 12] x [2, 10], 162 - 80 =
// 82 m^2. The volume is 3 x 80 + 2 x 82 = 404.
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

TEST(SweepStepOntoOutline, TwoPartsTouchingAlongAnEdgeGiveEachPairItsOwnEdge) {
  Footprint fp = make_footprint({{{0, 0}, {12, 0}, {12, 12}, {0, 12}}, {{2, 2}, {2, 10}, {10, 10}, {10, 2}}}, 45.0);
  fp.profiles = {{"wall", {{0, 0}, {0, 10}}, {"wall"}},
                 {"soffit", {{0, 0}, {0, 3}, {1.5, 3}, {1.5, 10}}, {"wall", "soffit", "wall"}},
                 {"ledge", {{0, 0}, {0, 3}, {-2, 3}, {-2, 10}}, {"wall", "ledge", "wall"}}};
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) e.profile = 0;
  fp.loops[0].edges[1].profile = 1;  // the outline's east edge, (12, 0) -> (12, 12)
  fp.loops[1].edges[2].profile = 2;  // the courtyard's east edge, (10, 10) -> (10, 2)
  SweepOptions options;
  options.max_height = 5.0;
  const Surface s = sweep(fp, options);
  expect_valid(s);
  for (const std::string& line : check_faces_on_planes(fp, options, s, roof_tolerance(fp))) ADD_FAILURE() << line;
  EXPECT_NEAR(surface_volume(s), 404.0, 1e-9 * 404.0);
}

}  // namespace
}  // namespace procex::testing
