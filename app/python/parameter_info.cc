#include "app/python/parameter_info.h"

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include "app/python/python_json.h"

namespace py = pybind11;

namespace procex::python {
namespace {

py::object bound(const std::optional<double>& v) { return v ? py::object(py::float_(*v)) : py::object(py::none()); }

}  // namespace

py::object to_python(const Value& v) {
  if (!v || !v.type()->has_json()) return py::none();
  nlohmann::json j;
  v.type()->to_json(v.raw(), j);
  return from_json_text(j.dump());
}

Parameter parameter_info(const ParamDecl& decl, const Value& value) {
  return {decl.name,  decl.type->name(), decl.unit, decl.doc, "", "", to_python(value ? value : decl.default_value),
          to_python(decl.default_value), bound(decl.min), bound(decl.max), decl.choices};
}

void bind_parameter(py::module_& m) {
  py::class_<Parameter>(m, "Parameter", "A parameter as the declaration of its node describes it, with a value.")
      .def_readonly("name", &Parameter::name)
      .def_readonly("type", &Parameter::type, "The value type: float, int, bool, string, enum, list<float>, ...")
      .def_readonly("value", &Parameter::value, "The current value (the default for a node type's parameter).")
      .def_readonly("default", &Parameter::default_value, "The node declaration's default.")
      .def_readonly("min", &Parameter::min, "Inclusive lower bound (numbers), else None.")
      .def_readonly("max", &Parameter::max, "Inclusive upper bound (numbers), else None.")
      .def_readonly("unit", &Parameter::unit, "m, deg, ... or empty.")
      .def_readonly("doc", &Parameter::doc)
      .def_readonly("choices", &Parameter::choices, "The choices of an enum, else empty.")
      .def_readonly("node", &Parameter::node, "The id of the recipe's node it belongs to (exposed parameters).")
      .def_readonly("node_type", &Parameter::node_type, "That node's type (exposed parameters).")
      .def_readonly("property", &Parameter::property,
                    "Recipe.exposed_for: the footprint's property that set it (its value wins over set()), else None.")
      .def("__repr__", [](const Parameter& p) {
        return "<procex.Parameter " + p.name + ": " + p.type + " = " + std::string(py::repr(p.value)) +
               (p.unit.empty() ? "" : " " + p.unit) + ">";
      });
}

}  // namespace procex::python
