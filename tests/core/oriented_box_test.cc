// OrientedBox: a box holds its points; two boxes are parted only when their
// points lie more than both margins apart, near the origin and far from it;
// long thin point sets side by side, whose boxes along the axes overlap, are
// parted.
#include "core/geom/oriented_box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace procex {
namespace {

// A sliver: a few points along a random direction from `start`, spread
// across it by up to `width`.
std::vector<glm::dvec3> sliver(std::mt19937_64& rng, glm::dvec3 start, double length, double width) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0), along(0.0, 1.0);
  glm::dvec3 direction;
  do direction = {unit(rng), unit(rng), unit(rng)};
  while (glm::length(direction) < 0.1);
  direction = glm::normalize(direction);
  std::vector<glm::dvec3> out;
  for (int k = 0; k < 4; ++k)
    out.push_back(start + direction * (length * along(rng)) + glm::dvec3(unit(rng), unit(rng), unit(rng)) * width);
  return out;
}

double closest(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : a)
    for (const auto& q : b) best = std::min(best, glm::length(p - q));
  return best;
}

TEST(OrientedBox, HoldsItsPoints) {
  std::mt19937_64 rng(1);
  for (const glm::dvec3 origin : {glm::dvec3(0.0), glm::dvec3(5e5, 5e6, 0.0), glm::dvec3(1e9, -1e9, 10.0)}) {
    for (int round = 0; round < 2000; ++round) {
      const std::vector<glm::dvec3> pts = sliver(rng, origin, 50.0, 0.01);
      const OrientedBox box = oriented_box_of(pts, 0.0);
      EXPECT_NEAR(std::abs(glm::determinant(box.axes)), 1.0, 1e-12);
      for (const auto& p : pts)
        for (int k = 0; k < 3; ++k) EXPECT_LE(std::abs(glm::dot(p - box.centre, box.axes[k])), box.half[k]);
    }
  }
}

// Every pair of point sets is tested against the distance of their closest
// points: parted boxes mean more than both margins between them; half the
// pairs are placed so that they come within the margins, the rest at random.
TEST(OrientedBox, PartsOnlyPointsFartherApartThanBothMargins) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> shift(-60.0, 60.0), nudge(-1.0, 1.0);
  const double margin = 0.05;
  for (const glm::dvec3 origin : {glm::dvec3(0.0), glm::dvec3(5e5, 5e6, 0.0), glm::dvec3(1e9, -1e9, 10.0)}) {
    std::size_t parted = 0, near = 0;
    for (int round = 0; round < 20000; ++round) {
      const std::vector<glm::dvec3> a = sliver(rng, origin, 100.0, 0.02);
      std::vector<glm::dvec3> b = sliver(rng, origin + glm::dvec3(shift(rng), shift(rng), shift(rng)), 100.0, 0.02);
      if (round % 2 == 0) {  // b's first point within the margins of a's
        b[0] = a[round / 2 % a.size()] + glm::normalize(glm::dvec3(nudge(rng), nudge(rng), nudge(rng)) + 1e-3) *
                                             (2.0 * margin * std::abs(nudge(rng)));
        ++near;
      }
      const bool overlap = oriented_overlap(oriented_box_of(a, margin), oriented_box_of(b, margin));
      EXPECT_EQ(overlap, oriented_overlap(oriented_box_of(b, margin), oriented_box_of(a, margin)));
      if (!overlap) {
        ++parted;
        EXPECT_GT(closest(a, b), 2.0 * margin) << "round " << round;
      }
    }
    EXPECT_GT(parted, near / 4);  // the test parts boxes, it does not only say they overlap
  }
}

// Parallel slivers 100 m long running diagonally, 0.1 m apart: their boxes
// along the axes overlap over most of their extent; turned, they part.
TEST(OrientedBox, PartsDiagonalSliversSideBySide) {
  for (const glm::dvec3 origin : {glm::dvec3(0.0), glm::dvec3(1e9, -1e9, 10.0)}) {
    const glm::dvec3 along = glm::normalize(glm::dvec3(1.0, 1.0, 0.5));
    const glm::dvec3 across = glm::normalize(glm::cross(along, glm::dvec3(0.0, 0.0, 1.0)));
    const auto sliver_at = [&](double offset) {
      std::vector<glm::dvec3> pts;
      for (const double t : {0.0, 50.0, 100.0}) pts.push_back(origin + along * t + across * offset);
      pts.push_back(origin + along * 100.0 + across * (offset + 0.01));
      return pts;
    };
    const OrientedBox a = oriented_box_of(sliver_at(0.0), 0.01), b = oriented_box_of(sliver_at(0.1), 0.01);
    EXPECT_FALSE(oriented_overlap(a, b));
    EXPECT_TRUE(oriented_overlap(a, oriented_box_of(sliver_at(0.03), 0.01)));
  }
}

}  // namespace
}  // namespace procex
