// The sweep's event queue on its own: split candidates wait in per-corner
// lists with only the lowest of each in the height queue, and a list holds
// only its lowest few, working out the rest again when they run out. So the
// queue must still hand out every candidate lowest first, drop a dead
// corner's, list none above the cap, and hold O(n) candidates, not one per
// reflex corner and edge. The L-shape, every edge at 45 degrees:
//
//   (0,4) +---+ (2,4)
//         |   |
//         |   + (2,2)  <- the one reflex corner
//         |   +-------+ (4,2)
//         |           |
//   (0,0) +-----------+ (4,0)
#include "core/sweep/event_queue.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/sweep/driver.h"
#include "core/sweep/profile_event.h"

namespace procex::engine {
namespace {

constexpr int kReflex = 3;  // the corner at (2, 2): between edges 2 and 3

State loaded(const std::vector<glm::dvec2>& points, const Tolerances& tol, const SweepOptions& options = {}) {
  State st(tol, options);
  FaceGroup base;
  base.kind = FaceKind::Base;
  st.base_face = 0;
  st.faces.push_back(base);
  for (std::size_t j = 0; j < points.size(); ++j) st.sources.push_back(Source{static_cast<std::int32_t>(j)});
  load_loop(st, points, std::vector<double>(points.size(), 1.0), std::vector<std::string>(points.size()), 0, 0);
  return st;
}

State l_shape(const SweepOptions& options = {}) {
  return loaded({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, Tolerances{4.0}, options);
}

// A star of n corners with radii 100 and 90 m alternating, jittered by up to
// a millimetre so that its events do not all fall at one height: every
// second corner is reflex and can run into almost every edge.
std::vector<glm::dvec2> star(int n) {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < n; ++i) {
    const double r = (i % 2 == 0 ? 100.0 : 90.0) + 1e-3 * std::sin(12.9898 * i);
    const double a = 2.0 * M_PI * i / n;
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return points;
}

// The clustering scale sweep() tries first.
constexpr Tolerances kStarTolerances{200.0, Tolerances::retry_relative[0]};

std::vector<Candidate> drain(EventQueue& queue, const State& st) {
  std::vector<Candidate> out;
  while (!queue.empty())
    for (const Candidate& c : queue.pop_cluster(st)) out.push_back(c);
  return out;
}

// The edges the reflex corner's planes meet going up, straight from the
// planes: it runs along (-1, -1) and meets the sides y = 0 and x = 0 at height
// 1; the sides x = 4 and y = 4 move with it.
std::set<int> reflex_targets(const State& st) {
  std::set<int> out;
  const Corner& k = st.corners[kReflex];
  for (int e = 0; e < static_cast<int>(st.edges.size()); ++e) {
    if (e == k.prev_edge || e == k.next_edge) continue;
    const Plane& pl = st.edges[e].plane;
    const double rate = glm::dot(pl.n, k.velocity) - pl.k;
    if (rate < 0.0 && -pl.signed_distance(st.position(kReflex, 0.0), 0.0) / rate >= 0.0) out.insert(e);
  }
  return out;
}

TEST(EventQueue, HandsOutEveryCandidateLowestFirst) {
  State st = l_shape();
  ASSERT_TRUE(st.reflex(kReflex));
  EventQueue queue;
  schedule_all(st, queue);
  const std::vector<Candidate> all = drain(queue, st);
  std::set<int> split_edges;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (i > 0) {
      EXPECT_LE(all[i - 1].z, all[i].z) << "candidate " << i;
    }
    if (all[i].edge == kNone) continue;
    EXPECT_EQ(all[i].corner, kReflex) << "only the reflex corner can split the L";
    EXPECT_TRUE(split_edges.insert(all[i].edge).second) << "edge " << all[i].edge << " twice";
  }
  EXPECT_EQ(split_edges, reflex_targets(st));
  EXPECT_EQ(split_edges, (std::set<int>{0, 5}));
  // The spans that close: along x = 4 and y = 4 at height 1, y = 0 and x = 0
  // at height 2 (the two along the reflex corner's edges move with it).
  EXPECT_EQ(all.size(), split_edges.size() + 4u);
}

TEST(EventQueue, DropsTheCandidatesOfADeadCorner) {
  State st = l_shape();
  EventQueue queue;
  schedule_all(st, queue);
  st.corners[kReflex].alive = false;
  for (const Candidate& c : drain(queue, st)) EXPECT_NE(c.corner, kReflex);
}

TEST(EventQueue, ListsNothingAboveTheCap) {
  SweepOptions capped;
  capped.max_height = 0.5;  // below the reflex corner's splits (height 1)
  State st = l_shape(capped);
  EventQueue queue;
  schedule_all(st, queue);
  for (const Candidate& c : drain(queue, st)) {
    EXPECT_EQ(c.edge, kNone) << "split at height " << c.z;
  }
}

// The star's reflex corners each meet dozens of edges, many more than a list
// holds: it works them out again, several times over, and must hand out the
// same splits, each once, lowest first, as the planes say.
TEST(EventQueue, HandsOutEverySplitOfALongListOnce) {
  State st = loaded(star(96), kStarTolerances);
  EventQueue queue;
  schedule_all(st, queue);
  std::map<int, std::set<int>> expected;  // corner -> edges it meets going up
  std::size_t longest = 0;
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c) {
    if (!st.reflex(c)) continue;
    const Corner& k = st.corners[c];
    for (int e = 0; e < static_cast<int>(st.edges.size()); ++e) {
      if (e == k.prev_edge || e == k.next_edge) continue;
      const Plane& pl = st.edges[e].plane;
      const double rate = glm::dot(pl.n, k.velocity) - pl.k;
      if (rate < 0.0 && -pl.signed_distance(st.position(c, 0.0), 0.0) / rate >= 0.0) expected[c].insert(e);
    }
    longest = std::max(longest, expected[c].size());
  }
  ASSERT_GT(longest, 32u) << "the lists must run out several times";
  std::map<int, std::set<int>> handed;
  std::map<int, double> last;  // corner -> height of its last split
  for (const Candidate& c : drain(queue, st)) {
    if (c.edge == kNone) continue;
    EXPECT_TRUE(handed[c.corner].insert(c.edge).second) << "corner " << c.corner << ", edge " << c.edge << " twice";
    EXPECT_GE(c.z, last[c.corner]) << "corner " << c.corner;
    last[c.corner] = c.z;
  }
  EXPECT_EQ(handed, expected);
  EXPECT_EQ(queue.held(), 0u);
}

// What the whole sweep of a star holds in split candidates grows with n, not
// with n times its reflex corners (which took gigabytes at 10,000 vertices):
// four times the corners, about four times the candidates, never sixteen.
std::size_t peak_held_sweeping(int n) {
  State st = loaded(star(n), kStarTolerances);
  EventQueue queue;
  schedule_all(st, queue);
  ProfileEvents profile_events;
  run_events(st, queue, profile_events);
  EXPECT_TRUE(std::none_of(st.corners.begin(), st.corners.end(), [](const Corner& c) { return c.alive; }))
      << "the star's roof closes";
  return queue.peak_held();
}

TEST(EventQueue, HoldsSplitCandidatesInLinearMemory) {
  const std::size_t small = peak_held_sweeping(500), large = peak_held_sweeping(2000);
  EXPECT_GT(small, 0u);
  EXPECT_LT(large, 6 * small) << small << " candidates held at 500 corners, " << large << " at 2,000";
  EXPECT_LT(large, 8u * 2000u) << "a few per corner";
}

}  // namespace
}  // namespace procex::engine
