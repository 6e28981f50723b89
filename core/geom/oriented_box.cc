#include "core/geom/oriented_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/geom/symmetric_eigen.h"

namespace procex {

namespace {

// Added to every |cosine| between the two boxes' axes, so that an axis made
// from two nearly parallel edges (a cross product of rounding size) never
// parts boxes that meet.
constexpr double kParallelSlack = 1e-9;

}  // namespace

OrientedBox oriented_box_of(std::span<const glm::dvec3> points, double margin) {
  OrientedBox box;
  if (points.empty()) return box;
  glm::dvec3 mean{0.0};
  for (const glm::dvec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  glm::dmat3 covariance(0.0);
  double reach = 0.0;
  for (const glm::dvec3& p : points) {
    const glm::dvec3 d = p - mean;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) covariance[i][j] += d[i] * d[j];
    reach = std::max({reach, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  box.axes = symmetric_eigenvectors(covariance);
  glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  for (const glm::dvec3& p : points) {
    const glm::dvec3 d = p - mean;
    const glm::dvec3 along{glm::dot(d, box.axes[0]), glm::dot(d, box.axes[1]), glm::dot(d, box.axes[2])};
    lo = glm::min(lo, along);
    hi = glm::max(hi, along);
  }
  box.centre = mean + box.axes * ((lo + hi) * 0.5);
  // The coordinates' rounding in the mean, the projections and the centre
  // (each a few units in the last place of the largest coordinate), and the
  // axes' departure from orthonormal, all far inside this.
  const double rounding = 64.0 * std::numeric_limits<double>::epsilon() * (reach + glm::length(hi - lo));
  box.half = (hi - lo) * 0.5 + margin + rounding;
  return box;
}

bool oriented_overlap(const OrientedBox& a, const OrientedBox& b) {
  double r[3][3], abs_r[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      r[i][j] = glm::dot(a.axes[i], b.axes[j]);
      abs_r[i][j] = std::abs(r[i][j]) + kParallelSlack;
    }
  const glm::dvec3 d = b.centre - a.centre;
  const double t[3] = {glm::dot(d, a.axes[0]), glm::dot(d, a.axes[1]), glm::dot(d, a.axes[2])};
  for (int i = 0; i < 3; ++i)
    if (std::abs(t[i]) > a.half[i] + b.half[0] * abs_r[i][0] + b.half[1] * abs_r[i][1] + b.half[2] * abs_r[i][2])
      return false;
  for (int j = 0; j < 3; ++j)
    if (std::abs(t[0] * r[0][j] + t[1] * r[1][j] + t[2] * r[2][j]) >
        a.half[0] * abs_r[0][j] + a.half[1] * abs_r[1][j] + a.half[2] * abs_r[2][j] + b.half[j])
      return false;
  // The axes a_i x b_j, in a's frame.
  for (int i = 0; i < 3; ++i) {
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    for (int j = 0; j < 3; ++j) {
      const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      const double reach_a = a.half[i1] * abs_r[i2][j] + a.half[i2] * abs_r[i1][j];
      const double reach_b = b.half[j1] * abs_r[i][j2] + b.half[j2] * abs_r[i][j1];
      if (std::abs(t[i2] * r[i1][j] - t[i1] * r[i2][j]) > reach_a + reach_b) return false;
    }
  }
  return true;
}

}  // namespace procex
