// The exceptions the module raises: one Python class per kind of problem, all
// under procex.Error, carrying the message the CLI prints for the same problem
// and the location as attributes (file, where, node, loop, vertex, height, edges).
#pragma once

#include <exception>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "graph/diagnostic.h"

namespace procex::python {

enum class ErrorKind { Recipe, Parameter, Footprint, Evaluation, Sweep, Mesh };

// Registers procex.Error and its subclasses on m.
void bind_errors(pybind11::module_& m);

// Thrown from C++, turned into the Python class of its kind with `attributes`
// set on the instance (a C++ exception, so it may be thrown without the GIL).
struct PythonError {
  ErrorKind kind;
  std::string message;
  std::vector<std::pair<std::string, std::string>> text_attributes;
  std::vector<std::pair<std::string, long>> integer_attributes;
  std::vector<std::pair<std::string, double>> real_attributes;
  std::vector<int> edges;                 // SweepError.edges
  std::vector<Diagnostic> diagnostics;    // EvaluationError.diagnostics
};

[[noreturn]] void raise(ErrorKind kind, std::string message);

// Raises the procex error for an exception core/ threw (InputError ->
// FootprintError with loop and vertex, SweepError with height and edges,
// MeshError), the message as describe() words it.
[[noreturn]] void raise_core(const std::exception& e);

}  // namespace procex::python
