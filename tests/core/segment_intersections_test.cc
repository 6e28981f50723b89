// for_each_near_segment_pair: every pair of segments that come within twice
// the margin of each other is visited, once, near the origin and far from
// it, for spikes side by side running every way, short random segments and
// points; long diagonal spikes visit far fewer pairs than their overlapping
// boxes; and a plan's edges side by side, long and close, only about as many
// pairs as there are edges.
#include "core/geom/segment_intersections.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace procex {
namespace {

double point_to_segment(glm::dvec2 p, const Segment2& s) {
  const glm::dvec2 d = s.b - s.a;
  const double len2 = glm::dot(d, d);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - s.a, d) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (s.a + t * d));
}

// Closest approach of two segments that do not cross (crossing ones are
// found by the sign test).
double gap(const Segment2& i, const Segment2& j) {
  const auto side = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  };
  if (side(i.a, i.b, j.a) * side(i.a, i.b, j.b) < 0 && side(j.a, j.b, i.a) * side(j.a, j.b, i.b) < 0) return 0.0;
  return std::min({point_to_segment(i.a, j), point_to_segment(i.b, j), point_to_segment(j.a, i),
                   point_to_segment(j.b, i)});
}

// Spikes out from a ring (the random star-shaped plan's edges), short
// segments anywhere and a few points, around origin.
std::vector<Segment2> mixed(std::mt19937_64& rng, glm::dvec2 origin, std::size_t n) {
  std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi), radius(50.0, 100.0), at(-100.0, 100.0),
      step(-2.0, 2.0);
  std::vector<Segment2> out;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = turn(rng);
    const glm::dvec2 dir{std::cos(a), std::sin(a)};
    if (k % 3 == 0) {
      out.push_back(
          {origin + dir * radius(rng), origin + (dir + glm::dvec2(step(rng), step(rng)) * 0.01) * radius(rng)});
    } else if (k % 3 == 1) {
      const glm::dvec2 p = origin + glm::dvec2(at(rng), at(rng));
      out.push_back({p, p + glm::dvec2(step(rng), step(rng))});
    } else {
      const glm::dvec2 p = origin + glm::dvec2(at(rng), at(rng)) * 0.01;
      out.push_back({p, k % 6 == 2 ? p : p + glm::dvec2(step(rng), step(rng)) * 0.001});
    }
  }
  return out;
}

TEST(SegmentIntersections, VisitsEveryNearPairOnce) {
  std::mt19937_64 rng(7);
  for (const glm::dvec2 origin : {glm::dvec2(0.0), glm::dvec2(5e5, 5e6), glm::dvec2(1e9, -1e9)}) {
    for (const double within : {0.0, 1e-3, 0.05}) {
      const std::vector<Segment2> segments = mixed(rng, origin, 1500);
      std::set<std::pair<std::size_t, std::size_t>> visited;
      std::size_t visits = 0;
      for_each_near_segment_pair(segments, within, [&](std::size_t i, std::size_t j) {
        EXPECT_LT(i, j);
        visited.insert({i, j});
        ++visits;
        return true;
      });
      EXPECT_EQ(visits, visited.size()) << "a pair visited twice";
      std::size_t near = 0;
      for (std::size_t i = 0; i < segments.size(); ++i)
        for (std::size_t j = i + 1; j < segments.size(); ++j)
          if (gap(segments[i], segments[j]) <= 2.0 * within) {
            ++near;
            EXPECT_TRUE(visited.count({i, j})) << "segments " << i << " and " << j << " within " << within;
          }
      EXPECT_GT(near, 100u);
    }
  }
}

TEST(SegmentIntersections, StopsWhenToldTo) {
  std::mt19937_64 rng(8);
  const std::vector<Segment2> segments = mixed(rng, glm::dvec2(0.0), 600);
  std::size_t visits = 0;
  for_each_near_segment_pair(segments, 0.05, [&](std::size_t, std::size_t) { return ++visits < 5; });
  EXPECT_EQ(visits, 5u);
}

// 8,192 spikes 50 m long from a ring, every way round: each spike's box
// overlaps those of about a fifth of the others; the cells it passes hold
// only the spikes beside it (measured: 6 times fewer pairs).
TEST(SegmentIntersections, LongDiagonalSpikesVisitFewPairs) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi);
  std::vector<Segment2> spikes;
  for (int k = 0; k < 8192; ++k) {
    const double a = turn(rng);
    const glm::dvec2 dir{std::cos(a), std::sin(a)};
    spikes.push_back({dir * 50.0, dir * 100.0});
  }
  std::size_t visits = 0;
  for_each_near_segment_pair(spikes, 0.0, [&](std::size_t, std::size_t) { return ++visits, true; });
  std::size_t boxes_overlap = 0;
  for (std::size_t i = 0; i < spikes.size(); ++i)
    for (std::size_t j = i + 1; j < spikes.size(); ++j) {
      const glm::dvec2 lo_i = glm::min(spikes[i].a, spikes[i].b), hi_i = glm::max(spikes[i].a, spikes[i].b);
      const glm::dvec2 lo_j = glm::min(spikes[j].a, spikes[j].b), hi_j = glm::max(spikes[j].a, spikes[j].b);
      boxes_overlap += lo_i.x <= hi_j.x && lo_j.x <= hi_i.x && lo_i.y <= hi_j.y && lo_j.y <= hi_i.y;
    }
  EXPECT_LT(visits * 4, boxes_overlap) << visits << " pairs visited, " << boxes_overlap << " boxes overlap";
}

// The loop of a random star-shaped plan (bench/scale_inputs.py's `random`):
// edges 17 m long on average and, at 65,536 corners, 7 mm apart. The strips
// visit about 4 pairs an edge at 4,096 and 65,536 corners; a grid of sqrt(n)
// x sqrt(n) cells visited 16 and 83 (and at 262,144 corners the check of the
// plan's loops took 11 s): every cell an edge passes holds the edges beside it.
TEST(SegmentIntersections, EdgesSideBySideVisitFewPairsEach) {
  for (const std::size_t n : {4096u, 65536u}) {
    std::mt19937_64 rng(n);
    std::uniform_real_distribution<double> turn(0.0, 2.0 * std::numbers::pi), radius(50.0, 100.0);
    std::vector<double> angles(n);
    for (double& a : angles) a = turn(rng);
    std::sort(angles.begin(), angles.end());
    std::vector<glm::dvec2> corners;
    for (const double a : angles) corners.push_back(radius(rng) * glm::dvec2(std::cos(a), std::sin(a)));
    std::vector<Segment2> edges;
    for (std::size_t k = 0; k < n; ++k) edges.push_back({corners[k], corners[(k + 1) % n]});
    std::size_t visits = 0;
    for_each_near_segment_pair(edges, 1e-9, [&](std::size_t, std::size_t) { return ++visits, true; });
    EXPECT_GE(visits, n) << "every edge meets the next";
    EXPECT_LT(visits, 8 * n) << n << " edges";
  }
}

}  // namespace
}  // namespace procex
