// procex.batch: a recipe over many footprints in parallel, as `procex batch`
// evaluates them (evaluate_feature per building), returning the meshes; and
// procex.batch_iter, the same buildings handed over one at a time from a
// bounded window, in bounded memory.
#pragma once

#include <pybind11/pybind11.h>

namespace procex::python {

void bind_batch(pybind11::module_& m);

}  // namespace procex::python
