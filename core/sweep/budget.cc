#include "core/sweep/budget.h"

#include <algorithm>
#include <string>

#include "core/geom/error.h"

namespace procex::engine {

Budget::Budget(const SweepBudget& limits) : limits_(limits) {
  const auto now = std::chrono::steady_clock::now();
  // Beyond a year the limit is none (and the sum would overflow).
  const double seconds = limits.max_seconds > 0.0 ? std::min(limits.max_seconds, 3.2e7) : 3.2e7;
  deadline_ = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

void Budget::vertices_exceeded(double z) const {
  throw SweepBudgetError("sweep: refused after " + std::to_string(limits_.max_vertices) +
                             " vertices (the vertex budget): the footprint makes the sweep run away; raise the "
                             "budget (max_vertices) if it is really this large",
                         z, {});
}

void Budget::events_exceeded(double z) const {
  throw SweepBudgetError("sweep: refused after " + std::to_string(limits_.max_events) +
                             " potential events (the event budget): the footprint makes the sweep run away; raise "
                             "the budget (max_events) if it is really this large",
                         z, {});
}

void Budget::time_exceeded(double z) const {
  std::string seconds = std::to_string(limits_.max_seconds);
  seconds.erase(seconds.find_last_not_of('0') + 1);
  if (seconds.back() == '.') seconds.pop_back();
  throw SweepBudgetError("sweep: refused after " + seconds +
                             " s (the time budget): the footprint makes the sweep run away; raise the budget "
                             "(max_seconds) if it is really this slow",
                         z, {});
}

}  // namespace procex::engine
