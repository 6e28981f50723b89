// The sweep's event queue on its own: split candidates wait in per-corner
// lists with only the lowest of each in the height queue, so the queue must
// still hand out every candidate lowest first, drop a dead corner's, and list
// none above the cap. The L-shape, every edge at 45 degrees:
//
//   (0,4) +---+ (2,4)
//         |   |
//         |   + (2,2)  <- the one reflex corner
//         |   +-------+ (4,2)
//         |           |
//   (0,0) +-----------+ (4,0)
#include "core/sweep/event_queue.h"

#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/sweep/driver.h"

namespace procex::engine {
namespace {

constexpr int kReflex = 3;  // the corner at (2, 2): between edges 2 and 3

State l_shape(const SweepOptions& options = {}) {
  State st(Tolerances{4.0}, options);
  FaceGroup base;
  base.kind = FaceKind::Base;
  st.base_face = 0;
  st.faces.push_back(base);
  const std::vector<glm::dvec2> points{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}};
  for (std::size_t j = 0; j < points.size(); ++j) st.sources.push_back(Source{static_cast<std::int32_t>(j)});
  load_loop(st, points, std::vector<double>(points.size(), 1.0), std::vector<std::string>(points.size()), 0, 0);
  return st;
}

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

}  // namespace
}  // namespace procex::engine
