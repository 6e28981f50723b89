// PointGrid: a lookup by distance finds exactly the points within it, and one
// by box exactly those inside the box, each once, wherever the points lie and
// however the box compares with the cells; a box lookup stops when told to.
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

// Boxes from a fraction of a cell to wider than the points (then every point
// is looked at once rather than every cell), near the origin and far from it.
TEST(PointGrid, BoxFindsExactlyThePointsInsideEachOnce) {
  for (const glm::dvec2 origin : {glm::dvec2(0.0, 0.0), glm::dvec2(5e5, 5e6), glm::dvec2(-1e9, 1e9)}) {
    const std::vector<glm::dvec2> pts = scattered(3000, origin, 100.0, 2);
    PointGrid grid(2.0);
    for (std::uint32_t i = 0; i < pts.size(); ++i) grid.add(pts[i], i);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> at(-20.0, 120.0), size(0.0, 1.0);
    for (std::size_t k = 0; k < 200; ++k) {
      const double w = k % 4 == 0 ? 300.0 * size(rng) : 10.0 * size(rng);
      const glm::dvec2 lo = origin + glm::dvec2(at(rng), at(rng)), hi = lo + glm::dvec2(w, w * size(rng));
      std::vector<std::uint32_t> got, want;
      EXPECT_TRUE(grid.for_each_in_box(lo, hi, [&](std::uint32_t id, glm::dvec2) { return got.push_back(id), true; }));
      for (std::uint32_t i = 0; i < pts.size(); ++i)
        if (pts[i].x >= lo.x && pts[i].x <= hi.x && pts[i].y >= lo.y && pts[i].y <= hi.y) want.push_back(i);
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, want) << "box " << k;
    }
  }
}

TEST(PointGrid, BoxLookupStopsWhenTold) {
  PointGrid grid(1.0);
  for (std::uint32_t i = 0; i < 100; ++i) grid.add({i * 0.1, 0.0}, i);
  std::size_t visits = 0;
  EXPECT_FALSE(grid.for_each_in_box({0.0, -1.0}, {10.0, 1.0}, [&](std::uint32_t, glm::dvec2) { return ++visits < 5; }));
  EXPECT_EQ(visits, 5u);
  EXPECT_TRUE(PointGrid(1.0).for_each_in_box({0.0, 0.0}, {1.0, 1.0}, [](std::uint32_t, glm::dvec2) { return false; }));
}

}  // namespace
}  // namespace procex
