#include "core/sweep/budget.h"

#include <time.h>

#include <cstdio>
#include <string>

#include "core/geom/error.h"

namespace procex::engine {

Budget::Budget(const SweepBudget& limits, std::size_t plan_vertices)
    : limits_(limits),
      deadline_(limits.max_seconds > 0.0 && plan_vertices >= kClockedFromTheStart
                    ? thread_cpu_seconds() + limits.max_seconds
                    : 0.0) {}

double Budget::thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void Budget::vertices_exceeded(double z) const {
  throw SweepBudgetError("sweep: refused after " + std::to_string(limits_.max_vertices) +
                             " vertices (the vertex budget): the footprint makes the sweep run away; raise the "
                             "budget (max_vertices) if it is really this large",
                         z, {});
}

void Budget::corners_exceeded(double z) const {
  throw SweepBudgetError("sweep: refused after " + std::to_string(limits_.max_vertices) +
                             " corners (the vertex budget bounds them too): the footprint makes the sweep run away; "
                             "raise the budget (max_vertices) if it is really this large",
                         z, {});
}

void Budget::candidates_exceeded(double z) const {
  throw SweepBudgetError("sweep: refused with over " + std::to_string(limits_.max_vertices) +
                             " potential events at one height (the vertex budget bounds them too): the footprint "
                             "makes the sweep run away; raise the budget (max_vertices) if it is really this large",
                         z, {});
}

void Budget::events_exceeded(double z) const {
  throw SweepBudgetError("sweep: refused after " + std::to_string(limits_.max_events) +
                             " potential events (the event budget): the footprint makes the sweep run away; raise "
                             "the budget (max_events) if it is really this large",
                         z, {});
}

void Budget::time_exceeded(double z) const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", limits_.max_seconds);
  throw SweepBudgetError("sweep: refused after " + std::string(seconds) +
                             " CPU seconds (the time budget): the footprint makes the sweep run away; raise the "
                             "budget (max_seconds) if it is really this slow",
                         z, {});
}

}  // namespace procex::engine
