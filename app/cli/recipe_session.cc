#include "app/cli/recipe_session.h"

#include <ostream>

#include "graph/pxg.h"

namespace procex {

std::optional<Graph> load_recipe(const std::filesystem::path& file, const AllowedFolders& allowed, std::ostream& err) {
  try {
    PxgOptions options;
    options.allowed_folders = allowed;
    return load_pxg(file, options);
  } catch (const PxgError& e) {
    err << e.file() << ": " << (e.where().empty() ? "" : e.where() + ": ") << e.message() << "\n";
  } catch (const std::exception& e) {  // filesystem errors from resolving the path
    err << file.string() << ": " << e.what() << "\n";
  }
  return std::nullopt;
}

EvalOptions recipe_eval_options(const std::filesystem::path& file, const AllowedFolders& allowed) {
  EvalOptions options;
  options.folder = std::filesystem::absolute(file).parent_path();
  options.allowed_folders = allowed;
  return options;
}

Status apply_setting(Graph& graph, Bindings& bindings, const std::string& name, const std::string& text) {
  for (const ExposedParam& p : graph.exposed_params()) {
    if (p.name != name) continue;
    const ParamDecl& decl = graph.node(p.node)->decl().params()[p.param];
    Result<Value> v = value_from_text(*decl.type, text);
    if (!v) return Status::error("'" + name + "': " + v.message());
    return graph.set_exposed(name, *v);
  }
  if (const auto i = graph.input_index(name)) {
    Result<Value> v = value_from_text(*graph.inputs()[*i].type, text);
    if (!v) return Status::error("'" + name + "': " + v.message());
    bindings[name] = *v;
    return Status::ok();
  }
  return Status::error("the recipe has no exposed parameter or input named '" + name + "'");
}

bool apply_settings(Graph& graph, Bindings& bindings, const std::vector<std::string>& settings, std::ostream& err) {
  bool ok = true;
  for (const std::string& s : settings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) {
      err << "--set " << s << ": expected name=value\n";
      ok = false;
      continue;
    }
    if (Status st = apply_setting(graph, bindings, s.substr(0, eq), s.substr(eq + 1)); !st) {
      err << "--set " << s << ": " << st.message() << "\n";
      ok = false;
    }
  }
  return ok;
}

std::vector<std::string> mesh_outputs(const Graph& graph) {
  std::vector<std::string> names;
  for (const GraphOutput& o : graph.outputs())
    if (o.type == &value_type<MeshSet>()) names.push_back(o.name);
  return names;
}

Status set_on_extrude_nodes(Graph& graph, const BudgetSettings& settings) {
  std::vector<NodeId> extrudes;
  for (const auto& [id, node] : graph.nodes())
    if (!node.type->is_group() && node.decl().type_name() == "Extrude") extrudes.push_back(id);
  for (NodeId id : extrudes) {
    Status s = Status::ok();
    if (settings.max_vertices && s) s = graph.set_param(id, "max_vertices", Value::make(*settings.max_vertices));
    if (settings.max_events && s) s = graph.set_param(id, "max_events", Value::make(*settings.max_events));
    if (settings.max_seconds && s) s = graph.set_param(id, "max_seconds", Value::make(*settings.max_seconds));
    if (!s) return Status::error("Extrude node " + std::to_string(id) + ": " + s.message());
  }
  return Status::ok();
}

std::optional<MeshRecipe> open_mesh_recipe(const std::filesystem::path& file, const std::vector<std::string>& settings,
                                           const AllowedFolders& allowed, std::ostream& err,
                                           const std::string& preset, const BudgetSettings& budget) {
  std::optional<Graph> graph = load_recipe(file, allowed, err);
  if (!graph) return std::nullopt;
  MeshRecipe r{std::move(*graph), {}, {}, recipe_eval_options(file, allowed)};
  if (!preset.empty())
    if (Status s = r.graph.apply_preset(preset); !s) {
      err << "--preset " << preset << ": " << s.message() << "\n";
      return std::nullopt;
    }
  if (!apply_settings(r.graph, r.bindings, settings, err)) return std::nullopt;
  if (const Status s = set_on_extrude_nodes(r.graph, budget); !s) {
    err << file.string() << ": " << s.message() << "\n";
    return std::nullopt;
  }
  r.outputs = mesh_outputs(r.graph);
  if (r.outputs.empty()) {
    err << file.string() << ": the recipe has no graph output of type mesh\n";
    return std::nullopt;
  }
  return r;
}

MeshSet gather_meshes(const EvalResult& r) {
  MeshSet out;
  for (const OutputResult& o : r.outputs)
    if (const MeshSet* m = o.value.get_if<MeshSet>()) out.parts.insert(out.parts.end(), m->parts.begin(), m->parts.end());
  return out;
}

void print_diagnostics(const EvalResult& r, const std::filesystem::path& file, std::ostream& err) {
  for (const Diagnostic& d : r.diagnostics) err << file.string() << ": " << d.to_string() << "\n";
}

}  // namespace procex
