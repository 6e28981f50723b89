#include "app/python/recipe.h"

#include <optional>
#include <sstream>
#include <tuple>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "app/cli/feature_binding.h"
#include "app/python/errors.h"
#include "app/python/footprint_input.h"
#include "app/python/mesh_arrays.h"
#include "app/python/parameter_info.h"
#include "app/python/python_json.h"

namespace py = pybind11;

namespace procex::python {
namespace {

MeshRecipe open(const std::filesystem::path& file) {
  std::ostringstream err;
  std::optional<MeshRecipe> r = open_mesh_recipe(file, {}, {}, err);
  if (!r) {
    std::string message = err.str();
    while (!message.empty() && message.back() == '\n') message.pop_back();
    throw PythonError{ErrorKind::Recipe, message, {{"file", file.string()}}, {}, {}, {}, {}};
  }
  return std::move(*r);
}

struct Input {
  std::string name, type, doc;
  py::object default_value;
  bool required = false;
};

std::vector<Parameter> exposed(const Graph& graph) {
  std::vector<Parameter> out;
  for (const ExposedParam& p : graph.exposed_params()) {
    const Node& node = *graph.node(p.node);
    Parameter& info = out.emplace_back(parameter_info(node.decl().params()[p.param], node.params[p.param]));
    info.name = p.name;
    info.node = std::to_string(p.node);
    info.node_type = node.decl().type_name();
  }
  return out;
}

std::vector<Input> inputs(const Graph& graph) {
  std::vector<Input> out;
  for (const GraphInput& in : graph.inputs())
    out.push_back({in.name, in.type->name(), in.doc, to_python(in.default_value), in.default_value.empty()});
  return out;
}

}  // namespace

Recipe::Recipe(const std::filesystem::path& file) : file_(file), recipe_(open(file)), evaluator_(cache_, kEngineSalt) {}

void Recipe::set(const std::string& name, py::handle value) {
  const std::string text = setting_text(value);
  if (Status s = apply_setting(recipe_.graph, recipe_.bindings, name, text); !s)
    throw PythonError{ErrorKind::Parameter, file_.string() + ": set " + name + "=" + text + ": " + s.message(),
                      {{"name", name}}, {}, {}, {}, {}};
}

MeshRecipe Recipe::with(py::handle attributes) const {
  MeshRecipe r = recipe_;
  if (attributes.is_none()) return r;
  for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(attributes)) {
    const std::string name = py::str(key), text = setting_text(value);
    if (Status s = apply_setting(r.graph, r.bindings, name, text); !s)
      throw PythonError{ErrorKind::Parameter, file_.string() + ": attribute " + name + "=" + text + ": " + s.message(),
                        {{"name", name}}, {}, {}, {}, {}};
  }
  return r;
}

void Recipe::refuse(const GeoJsonFeature& feature, const FeatureEvaluation& e) const {
  throw PythonError{ErrorKind::Footprint, file_.string() + ": feature " + feature.id + ": " + e.reason(),
                    {{"file", file_.string()}, {"feature", feature.id}}, {}, {}, {}, {}};
}

std::vector<Parameter> Recipe::exposed_for(py::handle footprint) const {
  const GeoJsonFeature feature = feature_from_python(footprint);
  Graph graph = recipe_.graph;
  Bindings bindings = recipe_.bindings;
  EvalOptions options = recipe_.options;
  FeatureEvaluation refused;
  refused.binding_problems = bind_feature(graph, bindings, options, feature);
  if (!refused.binding_problems.empty()) refuse(feature, refused);
  std::vector<Parameter> out = exposed(graph);
  for (const auto& [property, value] : feature.properties)
    for (Parameter& p : out)
      if (p.name == setting_name(property)) p.property = py::str(property);
  return out;
}

py::list Recipe::evaluate(py::handle footprint, py::handle attributes) {
  // The recipe itself unless attributes change it: copying its graph costs about as much as evaluating the house.
  std::optional<MeshRecipe> changed;
  if (!attributes.is_none() && py::len(attributes) > 0) changed = with(attributes);
  const MeshRecipe& r = changed ? *changed : recipe_;
  if (footprint.is_none()) {
    EvalResult result;
    WrappedMeshes meshes;
    {
      py::gil_scoped_release release;
      result = evaluator_.evaluate(r.graph, r.bindings, r.outputs, r.options);
      if (result.ok()) meshes = wrap_all(gather_meshes(result));  // laying out the faces needs no GIL
    }
    last_stats_ = std::move(result.stats);
    warn(file_.string(), result.diagnostics);
    if (!result.ok()) raise_evaluation(file_, std::move(result.diagnostics));
    return to_list(meshes);
  }
  const GeoJsonFeature feature = feature_from_python(footprint);
  FeatureEvaluation e;
  WrappedMeshes meshes;
  {
    py::gil_scoped_release release;
    e = evaluate_feature(r, evaluator_, feature, /*parallel=*/true);
    if (e.ok) meshes = wrap_all(std::move(e.meshes));
  }
  last_stats_ = std::move(e.stats);
  if (!e.binding_problems.empty()) refuse(feature, e);
  warn(file_.string() + ": feature " + feature.id, e.diagnostics);
  if (!e.ok) raise_evaluation(file_, std::move(e.diagnostics));
  return to_list(meshes);
}

void raise_evaluation(const std::filesystem::path& file, std::vector<Diagnostic> diagnostics) {
  std::string message;
  for (const Diagnostic& d : diagnostics) {
    if (d.severity != Severity::kError) continue;
    if (!message.empty()) message += '\n';
    message.append(file.string()).append(": ").append(d.to_string());
  }
  if (message.empty()) message = file.string() + ": a mesh output is missing";
  throw PythonError{ErrorKind::Evaluation, message, {{"file", file.string()}}, {}, {}, {}, std::move(diagnostics)};
}

void warn(const std::string& where, const std::vector<Diagnostic>& diagnostics) {
  auto one = [](const std::string& text) {
    if (PyErr_WarnEx(PyExc_UserWarning, text.c_str(), 1) != 0) throw py::error_already_set();
  };
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::kWarning) one(where + ": " + d.to_string());
}

void bind_recipe(py::module_& m) {
  py::class_<Input>(m, "Input", "A graph input of a recipe (footprint, building_id, ...).")
      .def_readonly("name", &Input::name)
      .def_readonly("type", &Input::type)
      .def_readonly("doc", &Input::doc)
      .def_readonly("default", &Input::default_value, "Its default (None without one, or for footprints).")
      .def_readonly("required", &Input::required, "No default: it must be bound (a footprint for procex batch).")
      .def("__repr__", [](const Input& i) { return "<procex.Input " + i.name + ": " + i.type + ">"; });

  py::class_<Recipe, std::shared_ptr<Recipe>>(
      m, "Recipe",
      "A .pxg recipe: load it, set its exposed parameters, evaluate it to meshes. Evaluating again recomputes only "
      "the nodes a change reaches (each Recipe has its own result cache).")
      .def_static("load", [](const std::filesystem::path& path) { return std::make_shared<Recipe>(path); },
                  py::arg("path"), "Loads a recipe; RecipeError names the file and where it is wrong.")
      .def_property_readonly("path", [](const Recipe& r) { return r.file(); })
      .def_property_readonly("exposed", [](const Recipe& r) { return exposed(r.mesh_recipe().graph); },
                             "The exposed parameters: name, type, value, default, min, max, unit, doc, choices.")
      .def("exposed_for", &Recipe::exposed_for, py::arg("footprint"),
           "The exposed parameters as evaluate(footprint=...) binds them: a property of the footprint named like a "
           "parameter (lower case, other characters as '_') sets it, and Parameter.property names it. "
           "FootprintError when evaluate() would refuse the footprint.")
      .def_property_readonly("inputs", [](const Recipe& r) { return inputs(r.mesh_recipe().graph); },
                             "The graph inputs (footprint, building_id, ...).")
      .def_property_readonly("outputs", [](const Recipe& r) { return r.mesh_recipe().outputs; },
                             "The names of the mesh outputs evaluate() gathers.")
      .def("set", &Recipe::set, py::arg("name"), py::arg("value"),
           "Sets an exposed parameter (or binds a graph input) by name. A str is read as --set reads text; other "
           "values as JSON (numbers, bools, lists, NumPy arrays). ParameterError says why a value does not fit.")
      .def(
          "get",
          [](const Recipe& r, const std::string& name) -> py::object {
            for (const Parameter& p : exposed(r.mesh_recipe().graph))
              if (p.name == name) return p.value;
            if (const auto it = r.mesh_recipe().bindings.find(name); it != r.mesh_recipe().bindings.end())
              return to_python(it->second);
            throw PythonError{ErrorKind::Parameter, r.file().string() + ": no exposed parameter named '" + name + "'",
                              {{"name", name}}, {}, {}, {}, {}};
          },
          py::arg("name"), "The current value of an exposed parameter or bound graph input.")
      .def("evaluate", &Recipe::evaluate, py::arg("footprint") = py::none(), py::arg("attributes") = py::none(),
           "Evaluates the mesh outputs, returning a list of Mesh. footprint: a GeoJSON Feature or geometry dict, or "
           "loops of (x, y) points, bound as procex batch binds a feature (its id to building_id, its properties to "
           "the parameters of the same name). attributes: {name: value} set for this evaluation only, before the "
           "feature's properties. The GIL is released while it runs. Raises EvaluationError (node diagnostics), "
           "FootprintError, ParameterError; warnings become Python UserWarnings.")
      .def_property_readonly(
          "last_evaluation",
          [](const Recipe& r) {
            std::vector<std::tuple<std::string, std::string, std::string>> out;
            for (const NodeStats& n : r.last_stats().nodes) out.emplace_back(to_string(n.path), n.type, to_string(n.outcome));
            return out;
          },
          "What the last evaluate() did, per node it visited: (node path, node type, outcome), the outcome one of "
          "'computed', 'cache hit', 'pass-through', 'FAILED', 'input failed', 'cancelled'. After a set(), only the "
          "nodes the change reaches are computed; a cache hit's inputs are not visited.")
      .def("__repr__", [](const Recipe& r) { return "<procex.Recipe " + r.file().string() + ">"; });
}

}  // namespace procex::python
