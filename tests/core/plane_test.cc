// The sweep's plane algebra where it is ill-conditioned: edges collinear only
// up to the rounding of rotated coordinates, and three planes turned by
// slight angles from each other.
#include "core/sweep/plane.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace procex::engine {
namespace {

// Two hole edges of a grid plan rotated by 27.8 degrees and scaled by 250
// (generated grid seed 179): on one line in exact terms, 1.4e-10 apart in
// direction after rounding. Both lean at 60 degrees from the vertical.
TEST(Plane, CrossingOfNearlyParallelPlanesOfOneSlopeStaysOnBoth) {
  const double k = std::tan(60.0 * M_PI / 180.0);
  auto dir = [](glm::dvec2 a, glm::dvec2 b) { return (b - a) / std::hypot(b.x - a.x, b.y - a.y); };
  const glm::dvec2 a0{42.43424904346466, 3128.6947835683823}, a1{392.21880877017975, 2466.205966114998};
  const glm::dvec2 b0{-540.5400173664093, 4232.842812657356}, b1{-307.3503108024597, 3791.1836010217667};
  const Plane pa = Plane::through(a0, 0.0, dir(a0, a1), k);
  const Plane pb = Plane::through(b0, 0.0, dir(b0, b1), k);
  ASSERT_GT(std::abs(cross(pa.n, pb.n)), 1e-10);  // not parallel for the sweep: their corner moves by this
  ASSERT_LT(std::abs(cross(pa.n, pb.n)), 1e-9);
  const glm::dvec2 v = crossing_velocity(pa, pb);
  // Over the 1,300 m the corner rose in that plan, a relative error of 1e-6
  // (Cramer's rule here) put the roof's vertex 0.6 mm off both planes.
  EXPECT_NEAR(glm::dot(pa.n, v), k, 1e-14 * k);
  EXPECT_NEAR(glm::dot(pb.n, v), k, 1e-14 * k);
}

TEST(Plane, CrossingVelocitySolvesBothPlanesAtEveryAngle) {
  for (double turn = 1.0; turn < 360.0; turn += 7.0) {
    if (std::abs(turn - 180.0) < 1.0) continue;  // antiparallel: a ridge, no crossing velocity
    const double t = turn * M_PI / 180.0;
    const Plane pa = Plane::through({0.0, 0.0}, 0.0, {1.0, 0.0}, 0.7);
    const Plane pb = Plane::through({3.0, 1.0}, 0.0, {std::cos(t), std::sin(t)}, -1.9);
    const glm::dvec2 v = crossing_velocity(pa, pb);
    EXPECT_NEAR(glm::dot(pa.n, v), pa.k, 1e-12 / std::abs(std::sin(t))) << turn;
    EXPECT_NEAR(glm::dot(pb.n, v), pb.k, 1e-12 / std::abs(std::sin(t))) << turn;
  }
}

// The planes of three consecutive edges of a regular n-gon at 45 degrees,
// each turned by t = 2 pi / n from the last, meet where a move of d in the
// middle one moves them by about 2 sqrt(2) d / t^2 (and d / t^2 for each
// outer one): the meeting's condition is 4 sqrt(2) / t^2. At a million sides
// the determinant, t^3, is 2e-16 and the triple product of the rows as they
// stand is rounding's noise.
TEST(Plane, MeetingConditionOfThreeSlightlyTurnedPlanes) {
  for (const double n : {4096.0, 262144.0, 1048576.0}) {
    const double t = 2.0 * M_PI / n;
    auto plane = [&](double a) {
      return Plane::through({std::cos(a), std::sin(a)}, 0.0, {-std::sin(a), std::cos(a)}, 1.0);
    };
    const double condition = meeting_condition(plane(-t), plane(0.0), plane(t));
    EXPECT_NEAR(condition * t * t / (4.0 * std::sqrt(2.0)), 1.0, 1e-3) << n;
  }
  // Three walls of a square meet where the plan leaves a point free: no point at all.
  const Plane wall{{1.0, 0.0}, 0.0, 0.0};
  EXPECT_EQ(meeting_condition(wall, {{0.0, 1.0}, 0.0, 0.0}, {{-1.0, 0.0}, 0.0, -1.0}), HUGE_VAL);
}

}  // namespace
}  // namespace procex::engine
