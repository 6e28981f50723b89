// PointTree: a search sees every point in each part of the plane its caller
// does not rule out, once, and none it rules out by box; a convex region
// searched by its half-planes (as an ear is) gives exactly the points in it,
// near the origin and far from it; a search stops when told to.
#include "core/geom/point_tree.h"

#include <algorithm>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace procex {
namespace {

std::vector<std::pair<glm::dvec2, std::uint32_t>> scattered(std::size_t n, glm::dvec2 origin, double size,
                                                             std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> at(0.0, size);
  std::vector<std::pair<glm::dvec2, std::uint32_t>> out(n);
  for (std::uint32_t i = 0; i < n; ++i) out[i] = {origin + glm::dvec2(at(rng), at(rng)), i};
  return out;
}

TEST(PointTree, ARegionSearchedByItsHalfPlanesGivesExactlyItsPointsOnce) {
  for (const glm::dvec2 origin : {glm::dvec2(0.0, 0.0), glm::dvec2(5e5, 5e6), glm::dvec2(-1e9, 1e9)}) {
    const auto pts = scattered(3000, origin, 100.0, 1);
    const PointTree tree(pts);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> at(0.0, 100.0);
    for (std::size_t k = 0; k < 100; ++k) {
      // A triangle, counter-clockwise; a box is ruled out when all its corners
      // lie right of one side.
      glm::dvec2 t[3] = {origin + glm::dvec2(at(rng), at(rng)), origin + glm::dvec2(at(rng), at(rng)),
                         origin + glm::dvec2(at(rng), at(rng))};
      const auto cross = [](glm::dvec2 u, glm::dvec2 w, glm::dvec2 p) {
        return (w.x - u.x) * (p.y - u.y) - (w.y - u.y) * (p.x - u.x);
      };
      if (cross(t[0], t[1], t[2]) < 0) std::swap(t[1], t[2]);
      const auto right_of = [&](int e, glm::dvec2 lo, glm::dvec2 hi) {
        for (const glm::dvec2 c : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)})
          if (cross(t[e], t[(e + 1) % 3], c) >= 0) return false;
        return true;
      };
      std::vector<std::uint32_t> got, want;
      std::size_t seen = 0;
      const auto outside = [&](glm::dvec2 lo, glm::dvec2 hi) {
        return right_of(0, lo, hi) || right_of(1, lo, hi) || right_of(2, lo, hi);
      };
      EXPECT_TRUE(tree.search(outside, [&](std::uint32_t id, glm::dvec2 p) {
        ++seen;
        if (cross(t[0], t[1], p) >= 0 && cross(t[1], t[2], p) >= 0 && cross(t[2], t[0], p) >= 0) got.push_back(id);
        return true;
      }));
      for (const auto& [p, id] : pts)
        if (cross(t[0], t[1], p) >= 0 && cross(t[1], t[2], p) >= 0 && cross(t[2], t[0], p) >= 0) want.push_back(id);
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, want) << "triangle " << k;
      EXPECT_LE(seen, pts.size());
    }
  }
}

// A thin triangle across the points (an ear of a comb's bar): the search
// looks at the points near it, not at every point under its box.
TEST(PointTree, AThinTriangleLooksAtFewPoints) {
  std::vector<std::pair<glm::dvec2, std::uint32_t>> pts;
  for (std::uint32_t i = 0; i < 10000; ++i) pts.push_back({glm::dvec2(i, 1.0), i});
  const PointTree tree(pts);
  const glm::dvec2 a(0.0, 0.0), c(10000.0, 1.0);  // the long side of (a, (10000, 0), c), below the row but at its end
  std::size_t seen = 0;
  tree.search(
      [&](glm::dvec2 lo, glm::dvec2 hi) {
        // Ruled out when wholly left of c -> a (above the triangle's long side).
        for (const glm::dvec2 k : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)})
          if ((a.x - c.x) * (k.y - c.y) - (a.y - c.y) * (k.x - c.x) >= -1e-9) return false;
        return true;
      },
      [&](std::uint32_t, glm::dvec2) { return ++seen, true; });
  EXPECT_LT(seen, 100u);
}

TEST(PointTree, SearchStopsWhenTold) {
  const PointTree tree(scattered(500, {0.0, 0.0}, 10.0, 3));
  std::size_t visits = 0;
  EXPECT_FALSE(tree.search([](glm::dvec2, glm::dvec2) { return false; },
                           [&](std::uint32_t, glm::dvec2) { return ++visits < 5; }));
  EXPECT_EQ(visits, 5u);
  EXPECT_TRUE(PointTree().search([](glm::dvec2, glm::dvec2) { return false; },
                                 [](std::uint32_t, glm::dvec2) { return false; }));
}

}  // namespace
}  // namespace procex
