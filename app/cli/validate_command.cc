#include "app/cli/validate_command.h"

#include <ostream>

#include "app/cli/recipe_session.h"

namespace procex {

int run_validate(const ValidateCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::optional<Graph> graph = load_recipe(options.recipe, options.allowed_paths, err);
  if (!graph) return kExitUnusableInput;
  std::size_t errors = 0, warnings = 0;
  auto report = [&](const Diagnostic& d) {
    ++(d.severity == Severity::kError ? errors : warnings);
    err << options.recipe.string() << ": " << d.to_string() << "\n";
  };
  for (const Diagnostic& d : graph->validate()) report(d);
  // Hashing plans the whole evaluation (and finds unconnected inputs) without running a node;
  // graph inputs without a default are bound later, by --set or batch.
  ResultCache cache(1 << 20);
  Evaluator evaluator(cache, kEngineSalt);
  EvalOptions hash_options = recipe_eval_options(options.recipe, options.allowed_paths);
  hash_options.assume_inputs_bound = true;
  for (const Diagnostic& d : evaluator.hash_outputs(*graph, {}, {}, hash_options).diagnostics) report(d);
  // Not a problem: batch binds `footprint` per feature, --set binds the rest.
  for (const GraphInput& in : graph->inputs())
    if (in.default_value.empty())
      out << options.recipe.string() << ": note: input '" << in.name << "' (" << in.type->name()
          << ") has no default: bind it with --set, or with procex batch for 'footprint'\n";
  if (mesh_outputs(*graph).empty())
    ++warnings, err << options.recipe.string() << ": warning: no graph output of type mesh: procex eval has nothing to write\n";
  out << options.recipe.string() << ": " << graph->nodes().size() << " nodes, " << graph->links().size() << " links, "
      << graph->inputs().size() << " inputs, " << graph->outputs().size() << " outputs, "
      << graph->exposed_params().size() << " exposed parameters: " << errors << " errors, " << warnings
      << " warnings\n";
  return errors > 0 ? kExitEvaluationFailed : 0;
}

}  // namespace procex
