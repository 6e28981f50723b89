#include "app/cli/budget_settings.h"

namespace procex {

SweepBudget with_settings(SweepBudget budget, const BudgetSettings& settings) {
  if (settings.max_vertices) budget.max_vertices = static_cast<std::size_t>(*settings.max_vertices);
  if (settings.max_events) budget.max_events = static_cast<std::size_t>(*settings.max_events);
  if (settings.max_seconds) budget.max_seconds = *settings.max_seconds;
  return budget;
}

}  // namespace procex
