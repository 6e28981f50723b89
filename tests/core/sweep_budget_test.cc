// The sweep's budget (SweepBudget): past a limit the sweep stops with a
// SweepBudgetError naming it, whatever the input; within it nothing changes.
#include <sys/resource.h>

#include <chrono>
#include <random>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/error.h"
#include "core/sweep/budget.h"
#include "core/sweep/sweep.h"
#include "tests/core/sweep_states.h"
#include "tests/support/generators/size_plans.h"

namespace procex {
namespace {

std::vector<glm::dvec2> star(int n, double r_even, double r_odd) {
  std::vector<glm::dvec2> p;
  for (int k = 0; k < n; ++k) {
    const double r = k % 2 ? r_odd : r_even, a = 2 * M_PI * k / n;
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return p;
}

// The error a sweep with `budget` throws, or "" if it succeeds.
std::string refusal(const Footprint& fp, const SweepBudget& budget) {
  SweepOptions o;
  o.budget = budget;
  try {
    (void)sweep(fp, o);
  } catch (const SweepBudgetError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepBudget, VerticesPastTheLimitRefuseTheFootprint) {
  const Footprint fp = make_footprint({star(400, 100, 60)}, 45);
  SweepBudget b;
  b.max_vertices = 300;
  EXPECT_NE(refusal(fp, b).find("after 300 vertices (the vertex budget)"), std::string::npos) << refusal(fp, b);
  b.max_vertices = 0;  // no limit
  EXPECT_EQ(refusal(fp, b), "");
}

TEST(SweepBudget, EventsPastTheLimitRefuseTheFootprint) {
  const Footprint fp = make_footprint({star(400, 100, 60)}, 45);
  SweepBudget b;
  b.max_events = 1000;  // 200 reflex corners list 400 planes each
  EXPECT_NE(refusal(fp, b).find("potential events (the event budget)"), std::string::npos) << refusal(fp, b);
}

TEST(SweepBudget, TimePastTheLimitRefusesTheFootprint) {
  // Radii drawn (seeded) so events come at many heights: the clock is read
  // once every few dozen of them.
  std::vector<glm::dvec2> p;
  unsigned seed = 12345;
  for (int k = 0; k < 2000; ++k) {
    seed = seed * 1103515245u + 12345u;
    const double r = 50.0 + 50.0 * static_cast<double>(seed >> 16 & 0x7fff) / 32768.0, a = 2 * M_PI * k / 2000;
    p.push_back({r * std::cos(a), r * std::sin(a)});
  }
  SweepBudget b;
  b.max_seconds = 1e-9;
  const std::string why = refusal(make_footprint({p}, 45), b);
  EXPECT_NE(why.find("refused after 1e-09 CPU seconds (the time budget)"), std::string::npos) << why;
}

// This thread's CPU time as the kernel accounts it (getrusage, not the
// clock the budget reads).
double thread_rusage_seconds() {
  rusage u{};
  getrusage(RUSAGE_THREAD, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

void burn_cpu_until(double rusage_seconds) {
  volatile double sink = 0;
  while (thread_rusage_seconds() < rusage_seconds)
    for (int i = 0; i < 10000; ++i) sink = sink + std::sqrt(static_cast<double>(i));
}

// The time budget is spent by the sweep's thread running, not by the clock
// on the wall: a thread that waits (for a core on a busy machine; here it
// sleeps, which is deterministic) spends none of it, one that runs spends it.
TEST(SweepBudget, TimeIsTheSweepingThreadsCpuTime) {
  const double start = thread_rusage_seconds();
  SweepBudget limits;
  limits.max_seconds = 0.05;
  engine::Budget budget(limits, engine::Budget::kClockedFromTheStart);
  const auto check = [&budget] {
    for (int i = 0; i < 1000; ++i) budget.check_time(1.0);  // past the clock's stride
  };
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // four budgets of wall time
  EXPECT_NO_THROW(check());
  burn_cpu_until(start + 0.1);  // twice the budget of CPU time
  EXPECT_THROW(check(), SweepBudgetError);
}

// A small plan's clock starts at its first read: what ran before (a few
// batches of a small plan, here the test's own burning) is not counted, and
// the budget is then spent as for any plan.
TEST(SweepBudget, ASmallPlansClockStartsAtItsFirstRead) {
  SweepBudget limits;
  limits.max_seconds = 0.05;
  engine::Budget budget(limits, engine::Budget::kClockedFromTheStart - 1);
  const auto check = [&budget] {
    for (std::size_t i = 0; i < engine::Budget::kClockStride; ++i) budget.check_time(1.0);
  };
  burn_cpu_until(thread_rusage_seconds() + 0.1);
  EXPECT_NO_THROW(check());  // the first read
  burn_cpu_until(thread_rusage_seconds() + 0.1);
  EXPECT_THROW(check(), SweepBudgetError);
}

// Corners made at one point share its vertex: they count against the vertex
// budget apart, as many again.
TEST(SweepBudget, CornersPastTheLimitRefuseTheFootprint) {
  SweepBudget limits;
  limits.max_vertices = 100;
  engine::Budget budget(limits, engine::Budget::kClockedFromTheStart);
  for (int i = 0; i < 100; ++i) {
    budget.add_vertex(1.0);
    budget.add_corner(1.0);
  }
  try {
    budget.add_corner(1.0);
    ADD_FAILURE() << "the 101st corner passed";
  } catch (const SweepBudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("after 100 corners (the vertex budget"), std::string::npos) << e.what();
  }
}

// The 32,768-star of radii 100 and 90 (each moved by up to 1 mm): at each of
// the clustering scales from 1e-8 to 1e-5 its 16,384 reflex corners race to
// the centre and meet there within one batch, each meeting every plane
// (hundreds of millions of candidates, many GB). Both limits hold there: the
// candidates held at one height (counted as each corner's are gathered), and
// the time; and the refusals cost little memory. Under a budget of two
// vertices per plan vertex the finest scale, tried last, is refused too
// (after as many corners); under a million it tells the centre's events
// apart and closes (SweepRetries.ACentreRunningAwayAtEveryOtherScaleClosesAtTheFinest).
TEST(SweepBudget, ARunawayAtOnePointIsRefusedInBoundedTimeAndMemory) {
  std::mt19937_64 rng(5);
  const Footprint fp = make_footprint({testing::jittered_star(32768, 100.0, 90.0, 1e-3, rng).loops[0]}, 45);
  SweepBudget events;
  events.max_vertices = 2 * 32768;
  const std::string by_events = refusal(fp, events);
  EXPECT_NE(by_events.find("with over 65536 potential events at one height"), std::string::npos) << by_events;
  SweepBudget time;
  time.max_vertices = 0;
  time.max_seconds = 2.0;
  const std::string by_time = refusal(fp, time);
  EXPECT_NE(by_time.find("after 2 CPU seconds (the time budget)"), std::string::npos) << by_time;
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  EXPECT_LT(u.ru_maxrss, 1'500'000) << "peak KiB";
}

TEST(SweepBudget, DefaultsLeaveLargeInputsAlone) {
  EXPECT_EQ(refusal(make_footprint({star(1000, 100, 60)}, 45), SweepBudget{}), "");
}

}  // namespace
}  // namespace procex
