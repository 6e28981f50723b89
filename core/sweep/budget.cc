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

namespace {

// Every refusal names the limit passed (`passed`: "after 300 vertices (the
// vertex budget)") and the knob that raises it.
[[noreturn]] void refuse(const std::string& passed, const char* knob, const char* why_large, double z) {
  throw SweepBudgetError("sweep: refused " + passed + ": the footprint makes the sweep run away; raise the budget (" +
                             knob + ") if it is really this " + why_large,
                         z, {});
}

}  // namespace

void Budget::vertices_exceeded(double z) const {
  refuse("after " + std::to_string(limits_.max_vertices) + " vertices (the vertex budget)", "max_vertices", "large",
         z);
}

void Budget::corners_exceeded(double z) const {
  refuse("after " + std::to_string(limits_.max_vertices) + " corners (the vertex budget bounds them too)",
         "max_vertices", "large", z);
}

void Budget::candidates_exceeded(double z) const {
  refuse("with over " + std::to_string(limits_.max_vertices) +
             " potential events at one height (the vertex budget bounds them too)",
         "max_vertices", "large", z);
}

void Budget::events_exceeded(double z) const {
  refuse("after " + std::to_string(limits_.max_events) + " potential events (the event budget)", "max_events",
         "large", z);
}

void Budget::time_exceeded(double z) const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", limits_.max_seconds);
  refuse("after " + std::string(seconds) + " CPU seconds (the time budget)", "max_seconds", "slow", z);
}

}  // namespace procex::engine
