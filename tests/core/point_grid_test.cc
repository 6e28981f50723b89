// PointGrid: a lookup by distance finds exactly the points within it.
#include "core/geom/point_grid.h"

#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace procex {
namespace {

std::vector<glm::dvec2> scattered(std::size_t n, glm::dvec2 origin, double size, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> at(0.0, size);
  std::vector<glm::dvec2> out(n);
  for (glm::dvec2& p : out) p = origin + glm::dvec2(at(rng), at(rng));
  return out;
}

TEST(PointGrid, NearFindsExactlyThePointsWithinTheRadius) {
  const std::vector<glm::dvec2> pts = scattered(2000, {-3.0, 7.0}, 10.0, 1);
  PointGrid grid(0.4);
  for (std::uint32_t i = 0; i < pts.size(); ++i) grid.add(pts[i], i);
  for (std::size_t k = 0; k < 50; ++k) {
    const glm::dvec2 p = pts[k * 37];
    std::vector<std::uint32_t> got, want;
    grid.for_each_near(p, [&](std::uint32_t id, glm::dvec2) { got.push_back(id); });
    for (std::uint32_t i = 0; i < pts.size(); ++i)
      if (glm::length(pts[i] - p) <= 0.4) want.push_back(i);
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want);
  }
}

}  // namespace
}  // namespace procex
