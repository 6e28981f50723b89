// A cluster gathers the corners at its point from an index of each edge with
// many spans (core/sweep/edge_corners.h) rather than by visiting every span
// of every edge taking part. The index must gather what the visits do, in
// their order (where the planes do not fix the meeting point, the first of
// the slowest corners does): a sweep with every edge indexed and one with
// none make the same roof to the bit.
#include "core/sweep/edge_corners.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/sweep/driver.h"
#include "core/sweep/event_queue.h"
#include "core/sweep/profile_event.h"
#include "tests/core/sweep_states.h"

namespace procex::engine {
namespace {

State swept(const std::vector<glm::dvec2>& points, std::size_t indexed_from, const std::vector<double>& slopes = {},
            const SweepOptions& options = {}) {
  State st = loaded(points, kStarTolerances, options, slopes);
  st.corners_indexed_from = indexed_from;
  EventQueue queue;
  ProfileEvents profiles;
  schedule_all(st, queue);
  run_events(st, queue, profiles);
  return st;
}

void expect_indexed_as_visited(const std::vector<glm::dvec2>& points, const std::vector<double>& slopes = {},
                               const SweepOptions& options = {}) {
  const State indexed = swept(points, 0, slopes, options);
  const State visited = swept(points, SIZE_MAX, slopes, options);
  expect_same_roof(indexed, visited);
}

// The bar is cut at every tooth in one instant: each cluster there takes in
// the bar's edge, by then of hundreds of spans.
TEST(EdgeCorners, GatherWhatVisitingEverySpanGathersOnAComb) { expect_indexed_as_visited(comb(300)); }

TEST(EdgeCorners, GatherWhatVisitingEverySpanGathersOnARandomPolygon) {
  expect_indexed_as_visited(random_star_shaped(1500, 5));
}

// Clusters a millimetre apart in height: an index's places, taken at one
// height, drift by the time of the next query.
TEST(EdgeCorners, GatherWhatVisitingEverySpanGathersOnAJitteredStar) { expect_indexed_as_visited(star(1200)); }

// Every corner meets every plane at the apex, most at it by logic: a corner
// found there brings in edges, and with them corners between the edge being
// gathered and those.
TEST(EdgeCorners, GatherWhatVisitingEverySpanGathersAtTheApexOfAnExactStar) {
  std::vector<glm::dvec2> points;
  const int n = 600;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    points.push_back((i % 2 == 0 ? 100.0 : 90.0) * glm::dvec2(std::cos(a), std::sin(a)));
  }
  expect_indexed_as_visited(points);
}

// Rounding a thousand times coarser than near the origin.
TEST(EdgeCorners, GatherWhatVisitingEverySpanGathersFarFromTheOrigin) {
  std::vector<glm::dvec2> points = comb(120);
  for (glm::dvec2& p : points) p += glm::dvec2(512345.6, 5012345.7);
  expect_indexed_as_visited(points);
}

// Vertical walls, planes leaning out and a cap: corners that do not move, and
// corners faster than the planes.
TEST(EdgeCorners, GatherWhatVisitingEverySpanGathersWithMixedSlopesAndACap) {
  const std::vector<glm::dvec2> points = comb(150);
  for (const std::optional<double> cap : {std::optional<double>(), std::optional<double>(1.5)}) {
    SweepOptions options;
    options.max_height = cap;
    expect_indexed_as_visited(points, mixed_slopes(points.size()), options);
  }
}

// Corners made one at a time along one edge, some dying, with a query after
// each: every live corner within reach is found, and the index's upkeep
// grows as n log n. Merging every few corners made into one sorted list moved
// the whole list each time, n^1.5: a sixth of the 1,048,576-vertex comb's
// sweep, where the bar is cut at every tooth.
TEST(EdgeCorners, FindEveryCornerWithinReachForUpkeepOfNLogN) {
  for (const int n : {2048, 32768}) {
    State st = loaded({{0.0, 0.0}, {1e4, 0.0}, {1e4, 1.0}, {0.0, 1.0}}, kStarTolerances);
    const int e = 0;  // along x
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> along(0.0, 1e4);
    EdgeCorners index;
    std::vector<int> found;
    index.near(st, e, {0.0, 0.0}, 0.0, 1.0, found);
    const auto first = static_cast<int>(st.corners.size());
    for (int i = 0; i < n; ++i) {
      Corner k;
      k.prev_edge = 1;
      k.next_edge = e;
      k.base = {along(rng), 0.0};
      st.corners.push_back(k);
      if (i % 3 == 2) st.corners[static_cast<std::size_t>(first + i / 2)].alive = false;
      const glm::dvec2 p{along(rng), 0.0};
      const double reach = 5.0;
      found.clear();
      index.near(st, e, p, 0.0, reach, found);
      if (i % 97 != 0) continue;
      std::sort(found.begin(), found.end());
      for (int c = first; c < static_cast<int>(st.corners.size()); ++c) {
        const bool within = std::abs(st.corners[c].base.x - p.x) <= reach;
        const bool listed = std::binary_search(found.begin(), found.end(), c);
        ASSERT_TRUE(st.corners[c].alive ? listed || !within : !listed) << n << " " << i << " " << c;
      }
    }
    found.clear();
    index.between(st, e, 1, found);
    const auto between_0_and_1 = [](const Corner& k) {
      return k.alive && std::min(k.prev_edge, k.next_edge) == 0 && std::max(k.prev_edge, k.next_edge) == 1;
    };
    const auto live_between = std::count_if(st.corners.begin(), st.corners.end(), between_0_and_1);
    EXPECT_EQ(found.size(), static_cast<std::size_t>(live_between));
    const double log_n = std::log2(static_cast<double>(n));
    EXPECT_LE(static_cast<double>(index.moved()), 4.0 * n * log_n) << n;
  }
}

}  // namespace
}  // namespace procex::engine
