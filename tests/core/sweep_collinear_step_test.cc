// Straight-on neighbours that step by different amounts at one height (paper
// 4.4's horizontal runs on a line the paper's 4.5 would call ambiguous): the
// step of each stays its own, with a jog across the line between them. Built
// in code: a 10 x 6 rectangle whose front is two edges meeting at x = 5, the
// left one stepping out (or in) 1 m at 3 m, the right one not; and the same
// with the middle vertex off the line by less than the clustering distance.
// Checked by the mesh validator, the faces-on-planes property (which knows
// jogs, tests/support/roof_properties.h), and the soffit's or ledge's area
// and place, worked out by hand.
#include <cmath>
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

// Edge 0 runs from (0, 0) to (5, lift), edge 1 on to (10, 0); edge 0 steps by `out`.
Footprint split_front(double out, double lift) {
  Footprint fp = make_footprint({{{0, 0}, {5, lift}, {10, 0}, {10, 6}, {0, 6}}}, 45.0);
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

void expect_step_of_its_own(double out, double lift) {
  const Footprint fp = split_front(out, lift);
  const Surface roof = sweep(fp);
  expect_valid(roof);
  for (const std::string& line : check_faces_on_planes(fp, {}, roof, roof_tolerance(fp))) ADD_FAILURE() << line;
  // The step spans the left edge only: 5 m long, |out| deep, at 3 m.
  const StepFaces step = step_faces(roof);
  EXPECT_NEAR(step.area, 5.0 * std::abs(out), 1e-6);
  EXPECT_NEAR(step.y_min, std::min(0.0, -out), 1e-6);
  EXPECT_NEAR(step.y_max, std::max(0.0, -out), 1e-6);
  EXPECT_NEAR(step.z_min, 3.0, 1e-9);
  EXPECT_NEAR(step.z_max, 3.0, 1e-9);
}

TEST(SweepCollinearStep, OneOfTwoStraightEdgesStepsOut) { expect_step_of_its_own(1.0, 0.0); }
TEST(SweepCollinearStep, OneOfTwoStraightEdgesStepsIn) { expect_step_of_its_own(-1.0, 0.0); }
// Off the line by 1e-9 of the footprint: within the clustering distance, so straight.
TEST(SweepCollinearStep, OneOfTwoNearlyStraightEdgesStepsOut) { expect_step_of_its_own(1.0, 1e-8); }
TEST(SweepCollinearStep, OneOfTwoNearlyStraightEdgesStepsIn) { expect_step_of_its_own(-1.0, -1e-8); }

}  // namespace
}  // namespace procex::testing
