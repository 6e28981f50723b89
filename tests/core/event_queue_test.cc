// The sweep's event queue on its own: split candidates wait in per-corner
// lists with only the lowest of each in the height queue, and a list holds
// only its lowest few, working out the rest again when they run out. So the
// queue must still hand out every candidate lowest first, drop a dead
// corner's, list none above the cap, and hold O(n) candidates, not one per
// reflex corner and edge. Lists of many edges are worked out through a
// PlaneIndex, which must hand out what testing every edge gives, to the bit,
// for less than O(n) work each. The L-shape, every edge at 45 degrees:
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
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/sweep/driver.h"
#include "core/sweep/intersection_event.h"
#include "core/sweep/meeting_heights.h"
#include "core/sweep/profile_event.h"
#include "tests/core/sweep_states.h"

namespace procex::engine {
namespace {

constexpr int kReflex = 3;  // the corner at (2, 2): between edges 2 and 3

State l_shape(const SweepOptions& options = {}) {
  return loaded({{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}, Tolerances{4.0}, options);
}

std::vector<Candidate> drain(EventQueue& queue, State& st) {
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

// Pops and resolves every batch until the queue is empty, and checks the
// roof closed (no corner left alive); the largest batch.
std::size_t sweep_to_the_top(State& st, EventQueue& queue) {
  std::size_t largest = 0;
  while (!queue.empty()) {
    st.height = std::max(st.height, queue.next_height());
    const std::vector<Candidate>& batch = queue.pop_cluster(st);
    largest = std::max(largest, batch.size());
    resolve_intersections(st, queue, batch);
  }
  EXPECT_TRUE(std::none_of(st.corners.begin(), st.corners.end(), [](const Corner& c) { return c.alive; }))
      << "the roof closes";
  return largest;
}

// An exact star (radii 100 and 90 m, no jitter) has every edge at one
// distance from its centre: every reflex corner meets every edge's plane at
// the apex, at one height, so n^2 / 2 splits fall in one batch there. Every
// span closes at the apex too, so each split only repeats two collapses of
// the batch, and the queue hands out none of them (pop_cluster): the batch
// holds the n edge events and a few splits. Listing a corner's splits at the
// apex takes one pass over the edges, not one per kHeldMost of them: what the
// queue works out stays O(n^2), not O(n^3).
struct ApexWork {
  std::size_t largest_batch, worked;
};
ApexWork sweeping_exact_star(int n) {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    points.push_back((i % 2 == 0 ? 100.0 : 90.0) * glm::dvec2(std::cos(a), std::sin(a)));
  }
  State st = loaded(points, kStarTolerances);
  EventQueue queue;
  schedule_all(st, queue);
  const std::size_t largest = sweep_to_the_top(st, queue);
  return {largest, queue.worked()};
}

TEST(EventQueue, HandsOutTheApexOfAnExactStarInLinearMemory) {
  const int n = 2000;
  const ApexWork work = sweeping_exact_star(n);
  EXPECT_GE(work.largest_batch, static_cast<std::size_t>(n)) << "the apex is one batch of every edge event";
  EXPECT_LT(work.largest_batch, 2u * n) << "and few splits";
  EXPECT_LT(work.worked, static_cast<std::size_t>(n) * n) << "one pass per list at the apex";
}

// A square with k x k square holes (bench/scale_inputs.py's "holes": 2 m
// holes 1 m apart, every edge at 45 degrees). The edges along one line of
// walls are collinear, of one slope: their planes are the same to the bit.
// Every hole's corner meets the planes along two such lines at height 0.5,
// at the point where four holes' corners meet: k splits of each line in one
// batch, O(n^1.5) of them, of which only the edges of the two spans that end
// there can split anything. One split per plane, naming the edges with a
// span at the point, keeps the batch O(n).
struct HolesWork {
  std::size_t corners, largest_batch, peak_held;
};
HolesWork sweeping_square_with_holes(int k) {
  State st = loaded_loops(holes_plan(k), Tolerances{3.0 * k + 1.0, Tolerances::retry_relative[0]});
  // Listed through the PlaneIndex, as at scale.
  EventQueue queue(0);
  schedule_all(st, queue);
  const std::size_t corners = st.corners.size();
  const std::size_t largest = sweep_to_the_top(st, queue);
  return {corners, largest, queue.peak_held()};
}

TEST(EventQueue, MeetsTheSharedPlanesOfAGridOnce) {
  const HolesWork small = sweeping_square_with_holes(8), large = sweeping_square_with_holes(16);
  // A split per edge put 3,648 candidates in the batch at height 0.5 at 260
  // corners and 30,848 at 1,028, and held 25,013 at once; one per plane 904
  // and 3,848, and 6,945 held.
  EXPECT_LT(large.largest_batch, 6 * large.corners) << large.largest_batch << " candidates in one batch";
  EXPECT_LT(large.largest_batch, 5 * small.largest_batch)
      << small.largest_batch << " candidates in one batch at " << small.corners << " corners, "
      << large.largest_batch << " at " << large.corners;
  EXPECT_LT(large.peak_held, 8 * large.corners) << "a few held per corner";
}

bool same_bits(const Candidate& a, const Candidate& b) {
  return std::memcmp(&a.z, &b.z, sizeof a.z) == 0 && std::memcmp(&a.p, &b.p, sizeof a.p) == 0 &&
         a.corner == b.corner && a.next == b.next && a.edge == b.edge;
}

// Every list worked out through the PlaneIndex against the oracle of testing
// every edge: the same candidates in the same order, to the bit, each list
// handed out to its end (so worked out again many times over).
void expect_indexed_lists_as_every_edge(const std::vector<glm::dvec2>& points, const std::vector<double>& slopes,
                                        const SweepOptions& options = {}) {
  State every_state = loaded(points, kStarTolerances, options, slopes);
  State indexed_state = loaded(points, kStarTolerances, options, slopes);
  EventQueue every(SIZE_MAX), indexed(0);
  schedule_all(every_state, every);
  schedule_all(indexed_state, indexed);
  const std::vector<Candidate> expected = drain(every, every_state), got = drain(indexed, indexed_state);
  ASSERT_EQ(got.size(), expected.size());
  std::size_t splits = 0;
  for (std::size_t i = 0; i < got.size(); ++i) {
    ASSERT_TRUE(same_bits(got[i], expected[i]))
        << "candidate " << i << ": corner " << got[i].corner << " edge " << got[i].edge << " at " << got[i].z
        << ", expected corner " << expected[i].corner << " edge " << expected[i].edge << " at " << expected[i].z;
    splits += got[i].edge != kNone;
  }
  EXPECT_GT(splits, 20 * points.size()) << "the lists run out and are worked out again many times";
  EXPECT_EQ(indexed.held(), 0u);
}

TEST(EventQueue, IndexedListsHandOutWhatEveryEdgeGivesOnARandomPolygon) {
  const std::vector<glm::dvec2> points = random_star_shaped(1200, 7);
  expect_indexed_lists_as_every_edge(points, std::vector<double>(points.size(), 1.0));
}

TEST(EventQueue, IndexedListsHandOutWhatEveryEdgeGivesOnAStar) {
  expect_indexed_lists_as_every_edge(star(1000), std::vector<double>(1000, 1.0));
}

// Far from the origin (projected coordinates): the index's bounds are taken
// about its own origin, and must stay sound where the coordinates' rounding is
// a thousand times coarser.
TEST(EventQueue, IndexedListsHandOutWhatEveryEdgeGivesFarFromTheOrigin) {
  std::vector<glm::dvec2> points = random_star_shaped(1000, 3);
  for (glm::dvec2& p : points) p += glm::dvec2(512345.6, 5012345.7);
  expect_indexed_lists_as_every_edge(points, std::vector<double>(points.size(), 1.0));
}

// Slopes from vertical walls to planes leaning out (every corner then splits,
// and meets planes from outside), and a cap that cuts lists short.
TEST(EventQueue, IndexedListsHandOutWhatEveryEdgeGivesWithMixedSlopesAndACap) {
  const std::vector<glm::dvec2> points = random_star_shaped(900, 11);
  const std::vector<double> slopes = mixed_slopes(points.size());
  expect_indexed_lists_as_every_edge(points, slopes);
  SweepOptions capped;
  capped.max_height = 6.0;
  expect_indexed_lists_as_every_edge(points, slopes, capped);
}

// Whole sweeps, the lists made and remade as corners come and go (and the
// live edges' index with them): the roofs are the same to the bit. Returns
// how many splits each queue worked out, the index's first.
std::pair<std::size_t, std::size_t> expect_indexed_sweep_as_every_edge(const std::vector<glm::dvec2>& points,
                                                                       std::size_t indexed_from = 0) {
  State every_state = loaded(points, kStarTolerances), indexed_state = loaded(points, kStarTolerances);
  EventQueue every(SIZE_MAX), indexed(indexed_from);
  ProfileEvents every_profiles, indexed_profiles;
  schedule_all(every_state, every);
  run_events(every_state, every, every_profiles);
  schedule_all(indexed_state, indexed);
  run_events(indexed_state, indexed, indexed_profiles);
  expect_same_roof(indexed_state, every_state);
  return {indexed.worked(), every.worked()};
}

TEST(EventQueue, IndexedSweepsMakeTheSameRoofs) {
  expect_indexed_sweep_as_every_edge(random_star_shaped(1500, 5));
  expect_indexed_sweep_as_every_edge(star(1200));
}

// The index's point: on a random polygon of 16,000 corners (where the queue
// uses it by default) its lists work out a fraction of the splits that testing
// every edge for every reflex corner does, for the same roof.
TEST(EventQueue, IndexedListsWorkOutFarFewerSplits) {
  const auto [indexed, every] =
      expect_indexed_sweep_as_every_edge(random_star_shaped(16000, 5), EventQueue::kIndexedFrom);
  EXPECT_LT(3 * indexed, every) << indexed << " splits worked out through the index, " << every
                                << " testing every edge";
}

// Every edge of a random star-shaped polygon runs nearly through its centre,
// and its reflex corners race there: seen from where a corner starts, a node
// of lines at a spread of angles may meet it anywhere near the centre, so the
// search opened most nodes (a quarter of the planes, then gave up and tested
// every edge); seen from where the corner is at the highest meeting held,
// those lines pass by at their own small offsets, most of them still ahead.
TEST(EventQueue, IndexedListsTellApartLinesThroughOnePoint) {
  const auto [indexed, every] =
      expect_indexed_sweep_as_every_edge(random_star_shaped(16000, 5), EventQueue::kIndexedFrom);
  EXPECT_LT(20 * indexed, every) << indexed << " splits worked out through the index, " << every
                                 << " testing every edge";
}

// A corner crossing the centre of a random star-shaped plan meets nearly
// every line there within one batch (at 262,144 corners, tens of thousands
// each): the batch takes them all at once, so one search hands out every
// meeting up to the batch's top besides the lowest few above it. Worked out a
// few lowest at a time, each search went through the lines met before again
// and past a sixteenth of the planes gave up for one testing every plane.
TEST(EventQueue, IndexHandsOutABatchsMeetingsInOneSearch) {
  constexpr std::size_t kPlanes = 20000, kHold = 16;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), offset(-0.01, 0.01);
  std::vector<int> edge(kPlanes);
  std::vector<double> nx(kPlanes), ny(kPlanes), k(kPlanes, 1.0), c(kPlanes);
  for (std::size_t j = 0; j < kPlanes; ++j) {
    const double a = angle(rng);
    edge[j] = static_cast<int>(j);
    nx[j] = std::cos(a);
    ny[j] = std::sin(a);
    c[j] = offset(rng);
  }
  const PlaneIndex::Planes planes{edge.data(), nx.data(), ny.data(), k.data(), c.data()};
  // 60 m out, at 1,000 m per m of rise straight through the lines' point.
  const glm::dvec2 p{60.0, 0.3}, v{-1000.0, 0.0};
  std::vector<double> meet(kPlanes);
  const CornerPath path{p, v, 0.0, -1e-9, HUGE_VAL, false};
  meeting_heights(nx.data(), ny.data(), k.data(), c.data(), kPlanes, path, meet.data());
  std::vector<Meeting> expected;
  for (std::size_t j = 0; j < kPlanes; ++j)
    if (meet[j] != HUGE_VAL) expected.push_back({meet[j], edge[j]});
  const MeetingEarlier earlier{0.0};
  std::sort(expected.begin(), expected.end(), earlier);
  // A batch up to the middle meeting: half of those the corner meets.
  const double through = expected[expected.size() / 2].at;
  const std::size_t within_expected = expected.size() / 2 + 1;
  ASSERT_GT(within_expected, kPlanes / 5);
  PlaneIndex index;
  index.extend(planes, kPlanes, p);
  std::vector<Meeting> held, within;
  PlaneIndex::Scratch scratch;
  const std::optional<std::size_t> worked = index.lowest(
      planes, {path, kPlanes, {0.0, kNone}, through}, kHold, held, within, scratch);
  ASSERT_TRUE(worked) << "gave up";
  ASSERT_EQ(within.size(), within_expected);
  ASSERT_EQ(held.size(), kHold);
  std::sort(within.begin(), within.end(), earlier);
  std::sort(held.begin(), held.end(), earlier);
  for (std::size_t j = 0; j < within.size() + held.size(); ++j) {
    const Meeting& got = j < within.size() ? within[j] : held[j - within.size()];
    ASSERT_TRUE(got.at == expected[j].at && got.edge == expected[j].edge) << "meeting " << j;
  }
  // Those it hands out and a few more: testing every plane works out twice as many.
  EXPECT_LT(4 * *worked, 5 * (within.size() + held.size())) << *worked << " meetings worked out";
}

// A corner running along a wall meets no wall collinear with it. Far from the
// origin the two walls' lines round apart by an ulp or so, and their meeting
// was then wherever rounding put it: in a step's nested sweep a corner went
// along one wall and split the next 4 delta2 below the step's top, where
// nothing meets, and moved to (5e5, 5e6) the roof was another roof (angles
// seed 8865, tests/data/generated_angles_8865.geojson). A wall turned off the
// line by a milliradian is still met where it crosses.
TEST(EventQueue, ACornerRunningAlongAPlaneDoesNotMeetItsCollinearNeighbour) {
  constexpr double kScale = 20.0, kRelative = 1e-7;
  std::mt19937_64 rng(8865);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), far(-5e6, 5e6);
  const auto wall = [](glm::dvec2 a, glm::dvec2 b) {
    const glm::dvec2 d = glm::normalize(b - a), n{-d.y, d.x};  // the inside on the left
    return std::pair{n, glm::dot(n, a)};
  };
  for (int i = 0; i < 1000; ++i) {
    const double a = angle(rng);
    const glm::dvec2 d{std::cos(a), std::sin(a)}, start{far(rng), far(rng)};
    // Edges start-mid and mid-end on one line; the corner leaves `end` along it, back towards mid.
    const glm::dvec2 mid = start + 2.0 * d, end = mid + 1.0 * d;
    const auto [n, c] = wall(start, mid);
    const double nx[] = {n.x}, ny[] = {n.y}, k[] = {0.0}, cc[] = {c};
    const CornerPath path{end, -d, 0.0, -kRelative * kScale, HUGE_VAL, false, kRelative * kScale, kRelative};
    double meet = 0.0;
    meeting_heights(nx, ny, k, cc, 1, path, &meet);
    ASSERT_EQ(meet, HUGE_VAL) << "a corner at (" << end.x << ", " << end.y << ") running along the wall meets it at "
                              << meet;
    // Turned by a milliradian about a point 1.5 along the corner's way, the
    // corner on its inside.
    const double t = 1e-3;
    const glm::dvec2 turned{d.x * std::cos(t) - d.y * std::sin(t), d.x * std::sin(t) + d.y * std::cos(t)};
    const glm::dvec2 pivot = end - 1.5 * d;
    const auto [m, e] = wall(pivot + turned, pivot - turned);
    const double mx[] = {m.x}, my[] = {m.y}, ee[] = {e};
    meeting_heights(mx, my, k, ee, 1, path, &meet);
    ASSERT_NEAR(meet, 1.5, 1e-3) << "a corner at (" << end.x << ", " << end.y << ") and the turned wall";
  }
}

// Planes of one line (the edges between a comb's teeth) are never met by a
// corner that runs along it; the index's bounds alone could not tell, so it
// opened them all, gave up and tested every edge. (Those edges are one plane
// now, and a comb of 100 teeth has too few planes for the index's trees.)
TEST(EventQueue, IndexedListsPassTheCollinearEdgesOfAComb) {
  const auto [indexed, every] = expect_indexed_sweep_as_every_edge(comb(400));
  EXPECT_LT(3 * indexed, every) << indexed << " splits worked out through the index, " << every
                                << " testing every edge";
}

}  // namespace
}  // namespace procex::engine
