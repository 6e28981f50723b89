// procex.sweep: the engine on plain loops, without a recipe.
#pragma once

#include <pybind11/pybind11.h>

namespace procex::python {

void bind_sweep(pybind11::module_& m);

}  // namespace procex::python
