// A corner made while a batch is resolved may cut into a span that a later
// group of the batch collapses, and that split is resolved in the batch
// (resolve_intersections). Like the queue's lists, it leaves alone the planes
// of the cluster that made the corner where the corner starts: it meets them
// there because of that cluster.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/sweep/budget.h"
#include "core/sweep/driver.h"
#include "core/sweep/event_queue.h"
#include "core/sweep/profile_event.h"
#include "tests/core/sweep_states.h"
#include "tests/support/generators/size_plans.h"

namespace procex::engine {
namespace {

// This star's corners race to its centre at up to 213 m per m of rise. There
// a cluster's new corner (3005, 2823 in the 8,192-star of seed 11) met the
// plane of edge 2980, one of its own cluster's, where it started, at the
// span's end the cluster had made beside it; resolved as a split, that made
// both corners again, the same, at one point, and again, until the budget
// refused the footprint (a million corners, at every clustering scale). Now
// the sweep ends within a few corners per vertex at every scale, never by
// the budget: at the finer ones it leaves some of the centre's corners open
// or ends at a cluster whose planes miss their point (at 1e-7: a scale
// defeated, not a runaway), and sweep() closes the roof at the coarsest.
TEST(BatchNewCorners, ACornerDoesNotSplitItsOwnClustersPlanesWhereItStarts) {
  std::mt19937_64 rng(3);
  const std::vector<glm::dvec2> points = testing::jittered_star(1200, 100.0, 60.0, 1e-3, rng).loops[0];
  for (double relative : Tolerances::retry_relative) {
    SCOPED_TRACE(relative);
    SweepBudget limits;
    limits.max_vertices = 1'000'000;
    Budget budget(limits, points.size());
    State st = loaded(points, Tolerances{200.0, relative}, {}, {}, &budget);
    EventQueue queue;
    ProfileEvents profiles;
    schedule_all(st, queue);
    try {
      run_events(st, queue, profiles);
    } catch (const SweepBudgetError& e) {
      FAIL() << "ran away: " << e.what();
    } catch (const SweepError& e) {
      EXPECT_NE(std::string(e.what()).find("do not meet at one point"), std::string::npos) << e.what();
    }
    EXPECT_LT(st.corners.size(), 3 * points.size());
  }
}

}  // namespace
}  // namespace procex::engine
