// Merge: several meshes as one (no geometry is copied).
#include <nlohmann/json.hpp>

#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Version 1 had six fixed inputs.
void upgrade(int saved_version, nlohmann::json& params) {
  if (saved_version < 2) params["inputs"] = 6;
}

void declare(NodeDecl& d) {
  d.doc("Puts meshes together, in input order (unconnected inputs are skipped). The meshes stay separate solids: "
        "exporters write one mesh each.")
      .category("Geometry");
  d.param<std::int64_t>("inputs").default_value<std::int64_t>(2).range(1, static_cast<double>(kMaxPortCount))
      .sets_port_count().doc("how many mesh inputs the node has");
  for (std::size_t i = 1; i <= d.count_of("inputs"); ++i) {
    auto port = d.input<MeshSet>("mesh_" + std::to_string(i));
    if (i > 1) port.optional();
  }
  d.output<MeshSet>("mesh");
  d.upgrade(upgrade);
}

void evaluate(EvalContext& ctx) {
  MeshSet out;
  for (std::size_t i = 0; i < ctx.decl().inputs().size(); ++i)
    if (ctx.has_input(i))
      for (const TaggedMesh& part : ctx.input<MeshSet>(i).parts) out.parts.push_back(part);
  ctx.set_output(0, std::move(out));
}

}  // namespace
PROCEX_REGISTER_NODE("Merge", 2, declare, evaluate);
}  // namespace procex
