// Stretching between control points: the box's corners land exactly on them.
#include <gtest/gtest.h>

#include <glm/matrix.hpp>

#include "core/placement/placement_error.h"
#include "core/placement/stretch.h"

namespace procex {
namespace {

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

void expect_near(const glm::dvec3& got, const glm::dvec3& want, double tol = 1e-12) {
  EXPECT_LE(glm::length(got - want), tol) << vector_text(got) << " vs " << vector_text(want);
}

const Box3 kPillar{{-0.2, 0, 0}, {0.2, 3, 0.4}};

TEST(Stretch, BoxCornersLandOnTheControlPoints) {
  ControlPoints cp;
  cp.origin = {1, 2, 3};
  cp.x_end = {2, 2.5, 3};    // not perpendicular to the others: a shear
  cp.y_end = {1, 2, 7};
  cp.z_end = {0.5, 3, 3.2};
  const glm::dmat4 m = map_box(kPillar, cp);
  expect_near(apply(m, kPillar.lo), cp.origin);
  expect_near(apply(m, kPillar.lo + glm::dvec3(0.4, 0, 0)), cp.x_end);
  expect_near(apply(m, kPillar.lo + glm::dvec3(0, 3, 0)), cp.y_end);
  expect_near(apply(m, kPillar.lo + glm::dvec3(0, 0, 0.4)), cp.z_end);
  // the far corner: affine, so the sum of the three edges
  expect_near(apply(m, kPillar.hi), cp.x_end + cp.y_end + cp.z_end - 2.0 * cp.origin);
}

TEST(Stretch, AFlatAxisKeepsItsOwnScale) {
  const Box3 panel{{0, 0, 0}, {1, 2, 0}};
  ControlPoints cp;
  cp.z_end = {0, 0, 5};  // only the direction counts
  const glm::dmat4 m = map_box(panel, cp);
  expect_near(apply(m, {0, 0, 1}), {0, 0, 1});
}

TEST(Stretch, DegenerateControlPointsAreRefused) {
  ControlPoints cp;
  cp.x_end = cp.origin;
  EXPECT_THROW(map_box(kPillar, cp), PlacementError);
  cp = ControlPoints{};
  cp.z_end = {1, 1, 0};  // in the plane of the x and y edges
  try {
    map_box(kPillar, cp);
    FAIL() << "coplanar control points were accepted";
  } catch (const PlacementError& e) {
    EXPECT_NE(std::string(e.what()).find("lie in one plane"), std::string::npos) << e.what();
  }
}

// A pillar on a wall facing -y, its bottom on one anchor (2, 0, 0) and its
// top on another (2, 0, 5): 3 m of pillar stretched to 5 m.
TEST(Stretch, PillarBetweenTwoAnchors) {
  const Frame wall;  // along +x, up +z, normal -y
  const glm::dmat4 m = stretch_between(kPillar, wall, {2, 0, 0}, {2, 0, 5});
  expect_near(apply(m, {0, 0, 0}), {2, 0, 0});       // middle of the back, bottom
  expect_near(apply(m, {0, 3, 0}), {2, 0, 5});       // middle of the back, top
  expect_near(apply(m, {0.2, 3, 0.4}), {2.2, -0.4, 5});
  expect_near(apply(m, {-0.2, 1.5, 0.4}), {1.8, -0.4, 2.5});
  EXPECT_NEAR(glm::determinant(glm::dmat3(m)), 5.0 / 3.0, 1e-12);
}

// The top anchor is 1 m further along: the pillar leans, its bottom and top
// faces stay level and exactly on the anchors' heights.
TEST(Stretch, LeaningPillarKeepsItsEndsOnTheAnchors) {
  const Frame wall;
  const glm::dmat4 m = stretch_between(kPillar, wall, {2, 0, 0}, {3, 0, 5});
  for (double x : {-0.2, 0.2})
    for (double z : {0.0, 0.4}) {
      EXPECT_NEAR(apply(m, {x, 0, z}).z, 0.0, 1e-12);
      EXPECT_NEAR(apply(m, {x, 3, z}).z, 5.0, 1e-12);
    }
  expect_near(apply(m, {0, 3, 0}), {3, 0, 5});
}

TEST(Stretch, AlongAnotherAxisAndErrors) {
  const Frame wall;
  // x stretched from 1 to 4 (a beam along the wall), pivot the middle of y and the back.
  const glm::dmat4 m = stretch_between(kPillar, wall, {1, 0, 2}, {4, 0, 2}, 0, {0, 0.5, 0});
  expect_near(apply(m, {-0.2, 1.5, 0}), {1, 0, 2});
  expect_near(apply(m, {0.2, 1.5, 0}), {4, 0, 2});
  expect_near(apply(m, {0.2, 3, 0}), {4, 0, 3.5});
  EXPECT_THROW(stretch_between(kPillar, wall, {1, 0, 2}, {1, 0, 2}), PlacementError);
  EXPECT_THROW(stretch_between(kPillar, wall, {1, 0, 2}, {4, 0, 2}, 3), PlacementError);
  EXPECT_THROW(stretch_between(Box3{{0, 0, 0}, {1, 0, 1}}, wall, {0, 0, 0}, {0, 0, 1}), PlacementError);
}

// The window frame (x -0.6..0.6, y 0..1.5, z 0..0.1) fills a 3 x 2.5 m grid
// cell centred at (5, 0, 4), 0.25 m kept free all round.
TEST(Stretch, WindowFitsAGridCell) {
  const Box3 window{{-0.6, 0, 0}, {0.6, 1.5, 0.1}};
  Cell cell;
  cell.frame.origin = {5, 0, 4};
  cell.width = 3;
  cell.height = 2.5;
  const glm::dmat4 m = fit_to_cell(window, cell, 0.25);
  expect_near(apply(m, window.lo), {3.75, 0, 3});
  expect_near(apply(m, window.hi), {6.25, -0.1, 5});
  // A row has no height: the window keeps its own, standing on the row's line.
  cell.height = 0;
  expect_near(apply(fit_to_cell(window, cell, 0.25), window.hi), {6.25, -0.1, 5.5});
  EXPECT_THROW(fit_to_cell(window, cell, 1.5), PlacementError);
}

}  // namespace
}  // namespace procex
