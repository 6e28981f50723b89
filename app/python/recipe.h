// procex.Recipe: a .pxg recipe loaded once, its exposed parameters set from
// Python and evaluated as often as wanted. Each Recipe keeps its own result
// cache, so evaluating again after a change recomputes only the nodes the
// change reaches. Loading, settings and footprint binding are the command
// line's own (app/cli: open_mesh_recipe, apply_setting, evaluate_feature).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "app/cli/feature_binding.h"
#include "app/cli/recipe_session.h"
#include "app/python/parameter_info.h"
#include "graph/cache.h"
#include "graph/evaluator.h"

namespace procex::python {

class Recipe {
 public:
  explicit Recipe(const std::filesystem::path& file);  // raises RecipeError

  const std::filesystem::path& file() const { return file_; }
  const MeshRecipe& mesh_recipe() const { return recipe_; }
  Evaluator& evaluator() { return evaluator_; }

  // Sets an exposed parameter, or binds a graph input; raises ParameterError.
  void set(const std::string& name, pybind11::handle value);
  // A copy of the recipe with `attributes` set as set() would (for one evaluation).
  MeshRecipe with(pybind11::handle attributes) const;
  // The recipe's meshes; raises EvaluationError with the diagnostics.
  pybind11::list evaluate(pybind11::handle footprint, pybind11::handle attributes);
  // The exposed parameters as evaluating for `footprint` binds them (its
  // properties set those of the same name); raises FootprintError as evaluate() would.
  std::vector<Parameter> exposed_for(pybind11::handle footprint) const;
  // What the last evaluate() did per node (computed, cache hit, ...).
  const EvalStats& last_stats() const { return last_stats_; }

 private:
  // FootprintError for a feature bind_feature refused.
  [[noreturn]] void refuse(const GeoJsonFeature& feature, const FeatureEvaluation& e) const;

  std::filesystem::path file_;
  MeshRecipe recipe_;
  ResultCache cache_;
  Evaluator evaluator_;
  EvalStats last_stats_;
};

// Registers procex.Recipe, procex.Parameter and procex.Input on m.
void bind_recipe(pybind11::module_& m);

// The EvaluationError for a failed evaluation of `file`: one line per error
// diagnostic, as `procex eval` prints it.
[[noreturn]] void raise_evaluation(const std::filesystem::path& file, std::vector<Diagnostic> diagnostics);

// Python warnings (UserWarning) for warning diagnostics, prefixed by `where`.
void warn(const std::string& where, const std::vector<Diagnostic>& diagnostics);

}  // namespace procex::python
