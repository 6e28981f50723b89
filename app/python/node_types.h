// procex.node_types(): every registered node type with the documentation of
// its declaration (what `procex nodes --markdown` prints), for help() and stubs.
#pragma once

#include <pybind11/pybind11.h>

namespace procex::python {

void bind_node_types(pybind11::module_& m);

}  // namespace procex::python
