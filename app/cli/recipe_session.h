// What the recipe commands (eval, validate, stats, batch) share: loading a
// .pxg with errors that name the file and place, applying --set name=value to
// exposed parameters or graph inputs, and gathering the recipe's mesh outputs.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/budget_settings.h"
#include "graph/evaluator.h"
#include "graph/graph.h"
#include "nodes/support/mesh_labels.h"  // label_parameters
#include "nodes/values.h"

namespace procex {

// Exit codes of the recipe commands.
inline constexpr int kExitEvaluationFailed = 1;  // a node (or a building) failed
inline constexpr int kExitUnusableInput = 2;     // the recipe or an input cannot be read, an output not written

// Folders besides the recipe's own that its files may lie in (`--allow-path`,
// repeatable): a shared recipe reads and writes only inside its folder.
using AllowedFolders = std::vector<std::filesystem::path>;

// "file: where: message" for a PxgError. nullopt after writing the error to err.
std::optional<Graph> load_recipe(const std::filesystem::path& file, const AllowedFolders& allowed, std::ostream& err);

// Options for evaluating the recipe in `file`: its nodes resolve relative
// paths against the file's folder and keep to it and `allowed`.
EvalOptions recipe_eval_options(const std::filesystem::path& file, const AllowedFolders& allowed);

// Applies "name=value" assignments: to the exposed parameter of that name, else
// to the graph input of that name (added to bindings). False after writing
// each problem to err (unknown name, value that does not fit the type).
bool apply_settings(Graph& graph, Bindings& bindings, const std::vector<std::string>& settings, std::ostream& err);

// Sets one exposed parameter or binds one graph input from text; Status says
// why not. Used for --set and for GeoJSON properties in batch.
Status apply_setting(Graph& graph, Bindings& bindings, const std::string& name, const std::string& text);

// A recipe ready to evaluate for meshes: loaded, --preset then --set applied, its mesh outputs found.
struct MeshRecipe {
  Graph graph;
  Bindings bindings;
  std::vector<std::string> outputs;  // graph outputs of type mesh, never empty
  EvalOptions options;               // recipe_eval_options
};
// Sets the given limits on every Extrude node at the graph's top level (the
// nodes inside a group keep the group's own values). Refused values (out of
// the parameter's range) say which node refused.
Status set_on_extrude_nodes(Graph& graph, const BudgetSettings& settings);

// nullopt after writing the problem to err (load error, bad setting, no mesh
// output, a budget limit an Extrude node refuses). `budget`'s limits go on
// every top-level Extrude node.
std::optional<MeshRecipe> open_mesh_recipe(const std::filesystem::path& file, const std::vector<std::string>& settings,
                                           const AllowedFolders& allowed, std::ostream& err,
                                           const std::string& preset = {}, const BudgetSettings& budget = {});

// Names of the graph outputs whose type is "mesh", in order; empty if none.
std::vector<std::string> mesh_outputs(const Graph& graph);

// The parts of every mesh output of r, in output order.
MeshSet gather_meshes(const EvalResult& r);

// Writes every diagnostic of r to err as "file: error: node 3 (Extrude): ...".
void print_diagnostics(const EvalResult& r, const std::filesystem::path& file, std::ostream& err);

// The engine salt every recipe command evaluates with.
inline constexpr const char* kEngineSalt = "procex 0.1";

}  // namespace procex
