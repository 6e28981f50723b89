#include "app/python/errors.h"

#include "core/geom/error.h"
#include "nodes/support/errors.h"

namespace py = pybind11;

namespace procex::python {
namespace {

struct ErrorClass {
  ErrorKind kind;
  const char* name;
  const char* doc;
};

constexpr ErrorClass kClasses[] = {
    {ErrorKind::Recipe, "RecipeError",
     "The recipe file cannot be read: its message names the file and the line and column or JSON pointer "
     "(attributes file, where)."},
    {ErrorKind::Parameter, "ParameterError",
     "A value does not fit the exposed parameter or graph input it is given to, or no such name exists "
     "(attribute name)."},
    {ErrorKind::Footprint, "FootprintError",
     "A footprint or footprints file cannot be used: unreadable GeoJSON, a feature that cannot be read, a "
     "self-intersecting loop... (attributes file, feature, loop, vertex where known)."},
    {ErrorKind::Evaluation, "EvaluationError",
     "A node failed while evaluating the recipe; the message has one line per diagnostic as `procex eval` "
     "prints them (attribute diagnostics: a list of (severity, node path, node type, message))."},
    {ErrorKind::Sweep, "SweepError", "The sweep could not resolve an event (attributes height, edges)."},
    {ErrorKind::Mesh, "MeshError", "The swept surface could not be turned into a mesh."},
};

// Owned references, never released: the classes live as long as the interpreter.
py::handle& error_class(ErrorKind kind) {
  static py::handle classes[std::size(kClasses)];
  return classes[static_cast<int>(kind)];
}

void set_error(const PythonError& e) {
  py::handle cls = error_class(e.kind);
  py::object instance = cls(e.message);
  for (const auto& [name, value] : e.text_attributes) instance.attr(name.c_str()) = value;
  for (const auto& [name, value] : e.integer_attributes) instance.attr(name.c_str()) = value;
  for (const auto& [name, value] : e.real_attributes) instance.attr(name.c_str()) = value;
  if (e.kind == ErrorKind::Sweep) instance.attr("edges") = e.edges;
  if (e.kind == ErrorKind::Evaluation) {
    py::list diagnostics;
    for (const Diagnostic& d : e.diagnostics)
      diagnostics.append(py::make_tuple(d.severity == Severity::kError ? "error" : "warning", to_string(d.node), d.type,
                                        d.message));
    instance.attr("diagnostics") = diagnostics;
  }
  PyErr_SetObject(cls.ptr(), instance.ptr());
}

}  // namespace

void bind_errors(py::module_& m) {
  PyObject* base = PyErr_NewExceptionWithDoc(
      "procex.Error", "Every error procex raises; its message is what the procex command line prints for the same problem.",
      PyExc_Exception, nullptr);
  m.attr("Error") = py::handle(base);
  for (const ErrorClass& c : kClasses) {
    PyObject* cls = PyErr_NewExceptionWithDoc((std::string("procex.") + c.name).c_str(), c.doc, base, nullptr);
    m.attr(c.name) = py::handle(cls);
    error_class(c.kind) = cls;
  }
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const PythonError& e) {
      set_error(e);
    }
  });
}

void raise(ErrorKind kind, std::string message) { throw PythonError{kind, std::move(message), {}, {}, {}, {}, {}}; }

void raise_core(const std::exception& e) {
  PythonError error{ErrorKind::Mesh, describe(e), {}, {}, {}, {}, {}};
  if (const auto* in = dynamic_cast<const InputError*>(&e)) {
    error.kind = ErrorKind::Footprint;
    error.integer_attributes = {{"loop", in->loop()}, {"vertex", in->vertex()}};
  } else if (const auto* sweep = dynamic_cast<const SweepError*>(&e)) {
    error.kind = ErrorKind::Sweep;
    error.real_attributes = {{"height", sweep->height()}};
    error.edges = sweep->edge_ids();
  }
  throw error;
}

}  // namespace procex::python
