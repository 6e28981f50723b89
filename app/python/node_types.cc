#include "app/python/node_types.h"

#include <pybind11/stl.h>

#include "app/python/parameter_info.h"
#include "graph/registry.h"

namespace py = pybind11;

namespace procex::python {
namespace {

struct Port {
  std::string name, type, doc;
};

struct NodeInfo {
  std::string name, category, doc, markdown;
  int version = 1;
  std::vector<Port> inputs, outputs;
  std::vector<Parameter> params;
};

std::vector<Port> ports(const std::vector<PortDecl>& decls) {
  std::vector<Port> out;
  for (const PortDecl& p : decls) out.push_back({p.name, p.type->name(), p.doc});
  return out;
}

py::dict node_types() {
  py::dict out;
  for (const auto& type : NodeRegistry::global().all()) {
    const NodeDecl& d = type->decl;
    NodeInfo info{d.type_name(), d.category(), d.doc(), d.markdown(), d.version(), ports(d.inputs()), ports(d.outputs()), {}};
    for (const ParamDecl& p : d.params()) info.params.push_back(parameter_info(p, {}));
    out[py::str(d.type_name())] = std::move(info);
  }
  return out;
}

}  // namespace

void bind_node_types(py::module_& m) {
  py::class_<Port>(m, "Port", "An input or output of a node type.")
      .def_readonly("name", &Port::name)
      .def_readonly("type", &Port::type)
      .def_readonly("doc", &Port::doc);
  py::class_<NodeInfo>(m, "NodeType", "A node type as its declaration describes it.")
      .def_readonly("name", &NodeInfo::name)
      .def_readonly("category", &NodeInfo::category)
      .def_readonly("version", &NodeInfo::version)
      .def_readonly("doc", &NodeInfo::doc)
      .def_readonly("markdown", &NodeInfo::markdown, "Its documentation as procex nodes --markdown prints it.")
      .def_readonly("inputs", &NodeInfo::inputs)
      .def_readonly("outputs", &NodeInfo::outputs)
      .def_readonly("params", &NodeInfo::params, "Its parameters, each with its default as value.")
      .def("__repr__", [](const NodeInfo& n) { return "<procex.NodeType " + n.name + ">"; });
  m.def("node_types", &node_types,
        "Every node type a recipe may use, by name, with the documentation of its declaration (NodeType).");
}

}  // namespace procex::python
