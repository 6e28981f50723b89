// HorizontalRays: a ray from p to +x is shown every segment it crosses at or
// left of the limit, whether the segment sits in a tree (built and merged as
// segments are added) or among the latest few; and a search that lowers the
// limit as it finds hits still finds the nearest.
#include "core/geom/horizontal_rays.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

namespace procex {
namespace {

struct Segment {
  glm::dvec2 a, b;
};

// Where the ray from p to +x crosses s, if it does at or right of p.
double crossing(const Segment& s, glm::dvec2 p) {
  const double lo = std::min(s.a.y, s.b.y), hi = std::max(s.a.y, s.b.y);
  if (p.y < lo || p.y > hi) return std::numeric_limits<double>::infinity();
  const double x = s.a.y == s.b.y ? std::min(s.a.x, s.b.x) : s.a.x + (p.y - s.a.y) * (s.b.x - s.a.x) / (s.b.y - s.a.y);
  return x >= p.x ? x : std::numeric_limits<double>::infinity();
}

TEST(HorizontalRays, ShowsEverySegmentTheRayCrossesUpToTheLimit) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> at(0.0, 100.0), step(-3.0, 3.0);
  HorizontalRays rays;
  std::vector<Segment> segments;
  // Added in runs of different lengths: some sit in merged trees, the last
  // few are looked at one by one.
  for (const std::size_t run : {1u, 63u, 1u, 200u, 7u, 900u, 30u}) {
    for (std::size_t k = 0; k < run; ++k) {
      const glm::dvec2 a{at(rng), at(rng)};
      segments.push_back({a, a + glm::dvec2(step(rng), step(rng))});
      rays.add(segments.back().a, segments.back().b, static_cast<std::uint32_t>(segments.size() - 1));
    }
    for (int q = 0; q < 200; ++q) {
      const glm::dvec2 p{at(rng), at(rng)};
      for (const double limit : {std::numeric_limits<double>::infinity(), p.x + 10.0}) {
        std::set<std::uint32_t> shown;
        rays.along(p, limit, [&](std::uint32_t id) { shown.insert(id); });
        for (std::uint32_t i = 0; i < segments.size(); ++i) {
          if (const double x = crossing(segments[i], p); std::isfinite(x) && x <= limit) {
            EXPECT_TRUE(shown.count(i)) << "segment " << i << " of " << segments.size();
          }
        }
      }
      // Lowering the limit to each hit, as convex_partition does, ends at the nearest.
      double nearest = std::numeric_limits<double>::infinity(), limit = nearest;
      for (const Segment& s : segments) nearest = std::min(nearest, crossing(s, p));
      rays.along(p, limit, [&](std::uint32_t id) { limit = std::min(limit, crossing(segments[id], p)); });
      EXPECT_EQ(limit, nearest);
    }
  }
}

}  // namespace
}  // namespace procex
