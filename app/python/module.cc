// The procex Python module: recipes, the sweep engine and batches over the
// same core, graph and nodes as the procex command line.
#include <pybind11/pybind11.h>

#include "app/python/batch.h"
#include "app/python/errors.h"
#include "app/python/mesh_arrays.h"
#include "app/python/node_types.h"
#include "app/python/parameter_info.h"
#include "app/python/recipe.h"
#include "app/python/sweep.h"

PYBIND11_MODULE(procex, m) {
  namespace python = procex::python;
  m.doc() =
      "procex: procedural extrusions (Kelly & Wonka) for buildings. Load a .pxg recipe (Recipe.load), set its exposed "
      "parameters, evaluate it to meshes as NumPy arrays; run the sweep engine alone on loops (sweep); or a recipe "
      "over many footprints in parallel (batch, or batch_iter: one building at a time, in bounded memory). Errors are procex.Error subclasses carrying the command line's "
      "diagnostics.";
  m.attr("__version__") = PROCEX_VERSION;
  python::bind_errors(m);
  python::bind_mesh(m);
  python::bind_parameter(m);
  python::bind_recipe(m);
  python::bind_sweep(m);
  python::bind_batch(m);
  python::bind_node_types(m);
}
