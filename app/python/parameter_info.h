// procex.Parameter: a parameter as its node declaration describes it (type,
// range, unit, doc, choices), with a value; for a recipe's exposed parameters
// and for procex.node_types().
#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "graph/node_decl.h"

namespace procex::python {

struct Parameter {
  std::string name, type, unit, doc, node, node_type;
  pybind11::object value, default_value, min, max;
  std::vector<std::string> choices;
  pybind11::object property = pybind11::none();  // the feature property that set it (Recipe.exposed_for)
};

// decl's description with `value` (empty: its default); node and node_type left empty.
Parameter parameter_info(const ParamDecl& decl, const Value& value);

// A value as Python sees it, through its JSON form; None for types without one (footprints).
pybind11::object to_python(const Value& v);

void bind_parameter(pybind11::module_& m);

}  // namespace procex::python
