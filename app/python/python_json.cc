#include "app/python/python_json.h"

namespace py = pybind11;

namespace procex::python {

std::string json_text(py::handle value) {
  const py::module_ json = py::module_::import("json");
  const py::cpp_function plain([](py::handle v) -> py::object {
    if (py::hasattr(v, "tolist")) return v.attr("tolist")();  // NumPy arrays and scalars
    if (py::hasattr(v, "__fspath__")) return py::module_::import("os").attr("fspath")(v);
    throw py::type_error("cannot convert a " + std::string(py::str(v.get_type().attr("__name__"))) + " to JSON");
  });
  return json.attr("dumps")(value, py::arg("default") = plain, py::arg("allow_nan") = false).cast<std::string>();
}

std::string setting_text(py::handle value) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  return json_text(value);
}

py::object from_json_text(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

}  // namespace procex::python
