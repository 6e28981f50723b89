// Python values as JSON text and back, through Python's own json module
// (NumPy arrays and scalars become lists and numbers): how values cross into
// the graph's typed values (value_from_text), exactly as the CLI's --set text does.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

namespace procex::python {

// A str is returned as it is (so enums and strings take bare text, like --set);
// anything else as JSON.
std::string setting_text(pybind11::handle value);
// JSON text of any JSON-able Python value.
std::string json_text(pybind11::handle value);
pybind11::object from_json_text(const std::string& text);

}  // namespace procex::python
