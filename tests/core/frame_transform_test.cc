// Placing at a frame: matrices checked against hand-computed points.
#include <cmath>

#include <gtest/gtest.h>

#include <glm/matrix.hpp>

#include "core/placement/box.h"
#include "core/placement/frame_transform.h"
#include "core/placement/placement_error.h"

namespace procex {
namespace {

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

void expect_near(const glm::dvec3& got, const glm::dvec3& want) {
  EXPECT_NEAR(got.x, want.x, 1e-12) << vector_text(got) << " vs " << vector_text(want);
  EXPECT_NEAR(got.y, want.y, 1e-12) << vector_text(got) << " vs " << vector_text(want);
  EXPECT_NEAR(got.z, want.z, 1e-12) << vector_text(got) << " vs " << vector_text(want);
}

// A wall facing -y (the Frame default axes), anchored 3 m up at x = 10.
TEST(FrameTransform, LocalAxesGoAlongUpAndOut) {
  Frame f;
  f.origin = {10, 0, 3};
  const glm::dmat4 m = frame_matrix(f);
  expect_near(apply(m, {0, 0, 0}), {10, 0, 3});
  expect_near(apply(m, {1, 0, 0}), {11, 0, 3});   // x along the edge
  expect_near(apply(m, {0, 1, 0}), {10, 0, 4});   // y up the wall
  expect_near(apply(m, {0, 0, 1}), {10, -1, 3});  // z out of the wall
}

// A roof face rising at 3:4 towards +y: up = (0, 0.6, 0.8), normal = along x up.
TEST(FrameTransform, SlopingFace) {
  Frame f;
  f.origin = {0, 2, 5};
  f.up = {0, 0.6, 0.8};
  f.normal = {0, -0.8, 0.6};
  const glm::dmat4 m = frame_matrix(f);
  expect_near(apply(m, {0, 2, 0}), {0, 3.2, 6.6});
  expect_near(apply(m, {1, 0, 0.5}), {1, 1.6, 5.3});
}

// The pillar (x -0.2..0.2, y 0..3, z 0..0.4) on a wall facing +x at (5, 2, 0),
// pivot the middle of its front at the bottom, twice as wide, raised 1 m.
TEST(FrameTransform, PivotScaleOffset) {
  Frame f;
  f.origin = {5, 2, 0};
  f.along = {0, 1, 0};
  f.up = {0, 0, 1};
  f.normal = {1, 0, 0};
  const Box3 pillar{{-0.2, 0, 0}, {0.2, 3, 0.4}};
  FramePlacement p;
  p.pivot = pillar.at({0.5, 0, 1});  // (0, 0, 0.4)
  p.scale = {2, 1, 1};
  p.offset = {0, 1, 0};
  const glm::dmat4 m = place_at(f, p);
  // (0.2, 3, 0.4) - pivot = (0.2, 3, 0); scaled (0.4, 3, 0); + offset (0.4, 4, 0)
  expect_near(apply(m, {0.2, 3, 0.4}), {5, 2.4, 4});
  expect_near(apply(m, p.pivot), {5, 2, 1});
  // the back of the pillar is 0.4 m behind the face
  expect_near(apply(m, {0, 0, 0}), {4.6, 2, 1});
  EXPECT_NEAR(glm::determinant(glm::dmat3(m)), 2.0, 1e-12);
  p.scale = {-1, 1, 1};
  EXPECT_LT(glm::determinant(glm::dmat3(place_at(f, p))), 0.0);
}

TEST(FrameTransform, BadFramesAreRefusedByName) {
  Frame f;
  f.along = {2, 0, 0};
  EXPECT_THROW(frame_matrix(f), PlacementError);
  f = Frame{};
  f.up = {0.1, 0, 0.995};
  EXPECT_THROW(frame_matrix(f), PlacementError);
  f = Frame{};
  f.normal = {0, 1, 0};  // left-handed
  try {
    frame_matrix(f);
    FAIL() << "a left-handed frame was accepted";
  } catch (const PlacementError& e) {
    EXPECT_NE(std::string(e.what()).find("right-handed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("normal (0, 1, 0)"), std::string::npos) << e.what();
  }
  f = Frame{};
  f.origin.x = std::nan("");
  EXPECT_THROW(frame_matrix(f), PlacementError);
  FramePlacement p;
  p.scale = {1, 0, 1};
  EXPECT_THROW(place_at(Frame{}, p), PlacementError);
}

TEST(FrameTransform, OrthonormalFrameFromTwoDirections) {
  const Frame f = orthonormal_frame({1, 2, 3}, {2, 0, 0}, {1, 0, 1});
  expect_near(f.along, {1, 0, 0});
  expect_near(f.up, {0, 0, 1});
  expect_near(f.normal, {0, -1, 0});
  EXPECT_NO_THROW(frame_matrix(f));
  EXPECT_THROW(orthonormal_frame({0, 0, 0}, {1, 0, 0}, {-3, 0, 0}), PlacementError);
  EXPECT_THROW(orthonormal_frame({0, 0, 0}, {0, 0, 0}, {0, 0, 1}), PlacementError);
}

}  // namespace
}  // namespace procex
