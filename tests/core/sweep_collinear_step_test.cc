// Straight-on neighbours that step by different amounts at one height (paper
// 4.4's horizontal runs on a line the paper's 4.5 would call ambiguous): the
// step of each stays its own, with a jog across the line between them. Built
// in code: a 10 x 6 rectangle whose front is two edges meeting at x = 5, the
// left one stepping out (or in) 1 m at 3 m, the right one not; and the same
// with the middle vertex off the line by less than the clustering distance,
// or by more but less than the mesh's distance tolerance (where the exact
// answer would leave a sliver the mesh cannot hold), and by more than that
// (where the exact weighted skeleton's answer stands: the step runs on).
// Checked by the mesh validator, the faces-on-planes property (which knows
// jogs, tests/support/roof_properties.h), and the soffit's or ledge's area
// and place, worked out by hand.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/sweep/sweep.h"
#include "tests/core/sweep_expectations.h"
#include "tests/support/roof_properties.h"

namespace procex::testing {
namespace {

// Walls to 3 m, a step of `out` metres (out positive, in negative), then a roof at 45 degrees.
Profile stepping(double out) { return {"step", {{0, 0}, {0, 3}, {out, 3}, {out - 5, 8}}, {"wall", "step", "roof"}}; }
const Profile kHouse{"house", {{0, 0}, {0, 3}, {-5, 8}}, {"wall", "roof"}};

// Edge 0 runs from (0, 0) to (5, lift), edge 1 on to (width, 0); edge 0 steps by `out`.
Footprint split_front(double out, double lift, double width = 10.0) {
  Footprint fp = make_footprint({{{0, 0}, {5, lift}, {width, 0}, {width, 6}, {0, 6}}}, 45.0);
  fp.profiles = {kHouse, stepping(out)};
  for (EdgeSpec& e : fp.loops[0].edges) e.profile = 0;
  fp.loops[0].edges[0].profile = 1;
  return fp;
}

// The horizontal faces tagged "step": their area seen from above, and the
// range of their y and z.
struct StepFaces {
  double area = 0.0, y_min = HUGE_VAL, y_max = -HUGE_VAL, z_min = HUGE_VAL, z_max = -HUGE_VAL;
};

StepFaces step_faces(const Surface& s) {
  StepFaces r;
  for (const SurfaceFace& f : s.faces) {
    if (f.tag != "step") continue;
    for (const auto& loop : f.loops) {
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3 a = s.vertices[loop[i]], b = s.vertices[loop[(i + 1) % loop.size()]];
        r.area += 0.5 * (a.x * b.y - b.x * a.y);
        r.y_min = std::min(r.y_min, a.y);
        r.y_max = std::max(r.y_max, a.y);
        r.z_min = std::min(r.z_min, a.z);
        r.z_max = std::max(r.z_max, a.z);
      }
    }
  }
  r.area = std::abs(r.area);
  return r;
}

// The front split at (5, lift), checked, with its step `length` metres
// along the front, |out| deep, at 3 m, its edges within `slack` of that.
void expect_step(double out, double lift, double length, double slack) {
  const Footprint fp = split_front(out, lift);
  const Surface roof = sweep(fp);
  expect_valid(roof);
  for (const std::string& line : check_faces_on_planes(fp, {}, roof, roof_tolerance(fp))) ADD_FAILURE() << line;
  const StepFaces step = step_faces(roof);
  EXPECT_NEAR(step.area, length * std::abs(out), 1e-6 + length * slack);
  EXPECT_NEAR(step.y_min, std::min(0.0, -out), 1e-6 + slack);
  EXPECT_NEAR(step.y_max, std::max(0.0, -out), 1e-6 + slack);
  EXPECT_NEAR(step.z_min, 3.0, 1e-9);
  EXPECT_NEAR(step.z_max, 3.0, 1e-9);
}

// The step spans the left edge only: 5 m long (as far as its end is lifted).
void expect_step_of_its_own(double out, double lift) { expect_step(out, lift, 5.0, std::abs(lift)); }

TEST(SweepCollinearStep, OneOfTwoStraightEdgesStepsOut) { expect_step_of_its_own(1.0, 0.0); }
TEST(SweepCollinearStep, OneOfTwoStraightEdgesStepsIn) { expect_step_of_its_own(-1.0, 0.0); }
// Off the line by 1e-9 of the footprint: within the clustering distance, so straight.
TEST(SweepCollinearStep, OneOfTwoNearlyStraightEdgesStepsOut) { expect_step_of_its_own(1.0, 1e-8); }
TEST(SweepCollinearStep, OneOfTwoNearlyStraightEdgesStepsIn) { expect_step_of_its_own(-1.0, -1e-8); }
// Off the line by 6e-6 (the vertex from its neighbours' line: twice the lift),
// beyond the clustering distance (at most 1e-7 of the 11.7 m diagonal) but within the
// mesh's distance tolerance (1e-6 of it): exactly, the corner would run on
// 2.5 km for the 1 m step, far past the right edge, which would then lie
// within 6e-6 of the left edge's line along its whole length: a wedge no
// mesh can tell from a straight line. OSM way 37054313 has such corners
// (sweep_mixed_step_test).
TEST(SweepCollinearStep, OneOfTwoEdgesStraightToTheMeshStepsOut) { expect_step_of_its_own(1.0, 3e-6); }
TEST(SweepCollinearStep, OneOfTwoEdgesStraightToTheMeshStepsIn) { expect_step_of_its_own(-1.0, -3e-6); }

// The faces-on-planes check lets a jog turn from its edge's line by the turn
// of a corner its tolerance cannot tell from straight, and no further. On a
// 40 m front the corner 3.4e-5 off its neighbours' line turns by 6.9e-6, and
// the jog across it by half that from either edge: accepted under the roof's
// tolerance (1e-6 of the 40.4 m diagonal), off every plane of its edge under
// 1e-5, where the corner is one the check sees.
TEST(SweepCollinearStep, AJogTurnsOnlyWithACornerTheToleranceCannotSee) {
  const Footprint fp = split_front(1.0, 3e-5, 40.0);
  const Surface roof = sweep(fp);
  expect_valid(roof);
  for (const std::string& line : check_faces_on_planes(fp, {}, roof, roof_tolerance(fp))) ADD_FAILURE() << line;
  const std::vector<std::string> seen = check_faces_on_planes(fp, {}, roof, 1e-5);
  ASSERT_FALSE(seen.empty());
  EXPECT_NE(seen.front().find("off every plane of its edge"), std::string::npos) << seen.front();
}

// Off the line by 2 mm, a corner the mesh holds: the weighted skeleton's own
// answer. Stepping out at a reflex corner (or in at a convex one), the left
// edge's new line runs on past the corner (2.5 km before it meets the right
// edge's line), so the step spans the whole front, less a wedge at most
// 10 m x 1 mm thick between the right edge and the line through the left.
void expect_step_running_on(double out, double lift) { expect_step(out, lift, 10.0, 2.0 * std::abs(lift)); }

TEST(SweepCollinearStep, OneOfTwoEdgesTurningByADegreeFiftiethStepsOutAcrossBoth) { expect_step_running_on(1.0, 1e-3); }
TEST(SweepCollinearStep, OneOfTwoEdgesTurningByADegreeFiftiethStepsInAcrossBoth) { expect_step_running_on(-1.0, -1e-3); }

}  // namespace
}  // namespace procex::testing
