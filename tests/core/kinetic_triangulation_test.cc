// Split candidates from a kinetic triangulation of the cross-section
// (core/sweep/kinetic_triangulation.h): a corner lists only the spans facing
// it across its triangles, not every live plane. The roofs must be those of
// the lists of every plane, to the bit where the batches hold the same
// events, and the triangulation must tile the loops after every batch.
#include "core/sweep/kinetic_triangulation.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <tuple>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/sweep/driver.h"
#include "core/sweep/event_queue.h"
#include "core/sweep/intersection_event.h"
#include "core/sweep/profile_event.h"
#include "core/sweep/surface_output.h"
#include "tests/core/sweep_states.h"
#include "tests/support/roof_properties.h"

namespace procex::engine {
namespace {

struct Swept {
  State st;
  std::size_t worked = 0;
  bool triangulated = false;
  KineticTriangulation::Work work;
};

Swept swept(const std::vector<glm::dvec2>& points, const std::vector<double>& slopes, std::size_t triangulated_from) {
  Swept out{loaded(points, kStarTolerances, {}, slopes), 0, false, {}};
  EventQueue queue(EventQueue::kIndexedFrom, triangulated_from);
  ProfileEvents profiles;
  schedule_all(out.st, queue);
  run_events(out.st, queue, profiles);
  out.worked = queue.worked();
  out.triangulated = queue.triangulated();
  out.work = queue.triangulation().work();
  return out;
}

// Returns the triangulated sweep's counts.
Swept expect_triangulated_as_listed(const std::vector<glm::dvec2>& points, std::vector<double> slopes = {}) {
  if (slopes.empty()) slopes.assign(points.size(), 1.0);
  const Swept listed = swept(points, slopes, SIZE_MAX);
  Swept triangulated = swept(points, slopes, 0);
  EXPECT_FALSE(listed.triangulated);
  EXPECT_TRUE(triangulated.triangulated) << "the triangulation was left";
  expect_same_roof(triangulated.st, listed.st);
  return triangulated;
}

// Random weights: each edge its own slope, from steep to shallow.
std::vector<double> random_slopes(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> slope(0.3, 3.0);
  std::vector<double> slopes(n);
  for (double& s : slopes) s = slope(rng);
  return slopes;
}

TEST(KineticTriangulation, ListsTheSplitsOfEveryPlaneOnRandomPlans) {
  for (unsigned seed = 1; seed <= 8; ++seed) {
    SCOPED_TRACE(seed);
    const Swept t = expect_triangulated_as_listed(random_star_shaped(400 + 150 * static_cast<int>(seed), seed));
    EXPECT_GT(t.work.flips, 0u);
  }
}

TEST(KineticTriangulation, ListsTheSplitsOfEveryPlaneWithEachEdgeItsOwnSlope) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE(seed);
    const std::vector<glm::dvec2> points = random_star_shaped(600, 100 + seed);
    expect_triangulated_as_listed(points, random_slopes(points.size(), seed));
  }
}

// A tooth's two sides are antiparallel: their corners meet along a segment.
TEST(KineticTriangulation, ListsTheSplitsOfEveryPlaneOnAComb) { expect_triangulated_as_listed(comb(200)); }

// A jittered star's centre: hundreds of corners meet within an instant, and
// splits that wait there (on a plane, off its spans) decide how its groups
// rewire the spans; they are handed out round each batch's neighbourhood.
// At this one clustering scale the listing does not close every star (sweep()
// tries other scales); wherever it does, the triangulation must too. (Up to
// 3,400 corners: at 3,600 it does not yet, kinetic_triangulation.h.)
std::string star_roof_problem(int n, std::size_t triangulated_from) {
  State st = loaded_loops({star(n)}, kStarTolerances);
  EventQueue queue(EventQueue::kIndexedFrom, triangulated_from);
  ProfileEvents profiles;
  try {
    schedule_all(st, queue);
    run_events(st, queue, profiles);
    if (queue.triangulated() != (triangulated_from == 0)) return "the triangulation was left";
    Surface roof = build_surface(st);
    close_surface(roof, st.plan_position);
    const std::vector<std::string> problems = testing::check_valid_mesh(roof);
    return problems.empty() ? "" : problems.front();
  } catch (const std::exception& e) {
    return e.what();
  }
}

TEST(KineticTriangulation, JitteredStarsCloseWhereTheListingDoes) {
  int compared = 0;
  for (int n = 400; n <= 3400; n += 200) {
    SCOPED_TRACE(n);
    if (!star_roof_problem(n, SIZE_MAX).empty()) continue;
    ++compared;
    EXPECT_EQ(star_roof_problem(n, 0), "");
  }
  EXPECT_GE(compared, 9);
}

// Holes: the region between the loops is triangulated as one, and a hole's
// loop joins the outer one where a corner of either splits the other.
TEST(KineticTriangulation, ListsTheSplitsOfEveryPlaneRoundHoles) {
  const auto sweep_holes = [](std::size_t triangulated_from) {
    const int k = 6;
    Swept out{loaded_loops(holes_plan(k), Tolerances{3.0 * k + 1.0, Tolerances::retry_relative[0]}), 0, false, {}};
    EventQueue queue(EventQueue::kIndexedFrom, triangulated_from);
    ProfileEvents profiles;
    schedule_all(out.st, queue);
    run_events(out.st, queue, profiles);
    out.triangulated = queue.triangulated();
    return out;
  };
  const Swept listed = sweep_holes(SIZE_MAX), triangulated = sweep_holes(0);
  EXPECT_TRUE(triangulated.triangulated) << "the triangulation was left";
  // At height 0.5 every wall between two holes meets its neighbour in one
  // instant: the batches list those collisions in another order, so the
  // vertices come in another order. The same vertices, and a mesh that
  // validates.
  const auto sorted = [](std::vector<glm::dvec3> v) {
    std::sort(v.begin(), v.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
      return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
    });
    return v;
  };
  EXPECT_EQ(sorted(triangulated.st.vertices), sorted(listed.st.vertices));
  Surface roof = build_surface(triangulated.st);
  close_surface(roof, triangulated.st.plan_position);
  EXPECT_EQ(testing::check_valid_mesh(roof), std::vector<std::string>{});
}

// The point: a random plan's corners list a few spans each, where the index
// of every live plane hands out thousands. Which splits wait in a batch
// changes how its heights are rounded: the roof is the listing's to a
// nanometre, not to the bit, at this size.
TEST(KineticTriangulation, WorksOutFarFewerSplitsThanListingEveryPlane) {
  const std::vector<glm::dvec2> points = random_star_shaped(6000, 3);
  const std::vector<double> slopes(points.size(), 1.0);
  const Swept listed = swept(points, slopes, SIZE_MAX);
  const Swept triangulated = swept(points, slopes, 0);
  EXPECT_TRUE(triangulated.triangulated);
  ASSERT_EQ(triangulated.st.vertices.size(), listed.st.vertices.size());
  for (std::size_t v = 0; v < listed.st.vertices.size(); ++v)
    ASSERT_LT(glm::length(triangulated.st.vertices[v] - listed.st.vertices[v]), 1e-9) << "vertex " << v;
  ASSERT_EQ(triangulated.st.faces.size(), listed.st.faces.size());
  for (std::size_t f = 0; f < listed.st.faces.size(); ++f)
    EXPECT_EQ(triangulated.st.faces[f].half_edges.size(), listed.st.faces[f].half_edges.size()) << "face " << f;
  EXPECT_LT(30 * triangulated.worked, listed.worked) << triangulated.worked << " against " << listed.worked;
}

// Batch by batch, as run_events goes: after each, the triangles tile the loops.
TEST(KineticTriangulation, TilesTheLoopsAfterEveryBatch) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE(seed);
    State st = loaded(random_star_shaped(500, seed), kStarTolerances);
    EventQueue queue(EventQueue::kIndexedFrom, 0);
    schedule_all(st, queue);
    std::size_t batches = 0;
    for (;;) {
      queue.catch_up(st);
      if (queue.empty()) break;
      ASSERT_TRUE(queue.triangulated());
      ASSERT_TRUE(queue.triangulation().consistent(st)) << "after batch " << batches;
      st.height = std::max(st.height, queue.next_height());
      resolve_intersections(st, queue, queue.pop_cluster(st));
      ++batches;
    }
    EXPECT_GT(batches, 100u);
  }
}

}  // namespace
}  // namespace procex::engine
