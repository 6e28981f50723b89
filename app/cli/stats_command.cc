#include "app/cli/stats_command.h"

#include <ostream>

#include "app/cli/recipe_session.h"

namespace procex {

int run_stats(const StatsCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::optional<Graph> graph = load_recipe(options.recipe, options.allowed_paths, err);
  if (!graph) return kExitUnusableInput;
  Bindings bindings;
  if (!apply_settings(*graph, bindings, options.settings, err)) return kExitUnusableInput;
  ResultCache cache;
  Evaluator evaluator(cache, kEngineSalt);
  const EvalOptions eval_options = recipe_eval_options(options.recipe, options.allowed_paths);
  const EvalResult cold = evaluator.evaluate(*graph, bindings, {}, eval_options);
  print_diagnostics(cold, options.recipe, err);
  out << options.recipe.string() << ": first evaluation\n";
  cold.stats.print(out);
  const EvalResult warm = evaluator.evaluate(*graph, bindings, {}, eval_options);
  const CacheCounters c = cache.counters();
  out << "second evaluation: " << warm.stats.count(NodeOutcome::kCacheHit) << " cache hits, "
      << warm.stats.computed() << " computed, " << static_cast<double>(warm.stats.total_ns) / 1e6 << " ms\n"
      << "cache: " << c.entries << " entries, " << c.bytes << " bytes\n";
  return cold.ok() ? 0 : kExitEvaluationFailed;
}

}  // namespace procex
