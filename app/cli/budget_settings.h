// The sweep budget given on the command line (--max-vertices, --max-events,
// --max-seconds): `procex roof` sweeps with it, `procex eval` and `batch` set
// each given limit on every Extrude node of the recipe.
#pragma once

#include <cstdint>
#include <optional>

#include "core/sweep/sweep.h"

namespace procex {

struct BudgetSettings {
  std::optional<std::int64_t> max_vertices, max_events;
  std::optional<double> max_seconds;
};

// `budget` with the given limits in place of its own.
SweepBudget with_settings(SweepBudget budget, const BudgetSettings& settings);

}  // namespace procex
