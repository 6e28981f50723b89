// Merge: several meshes as one (no geometry is copied).
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

constexpr std::size_t kInputs = 6;

void declare(NodeDecl& d) {
  d.doc("Puts up to six meshes together, in input order (unconnected inputs are skipped). The meshes stay "
        "separate solids: exporters write one mesh each.")
      .category("Geometry");
  for (std::size_t i = 1; i <= kInputs; ++i) {
    auto port = d.input<MeshSet>("mesh_" + std::to_string(i));
    if (i > 1) port.optional();
  }
  d.output<MeshSet>("mesh");
}

void evaluate(EvalContext& ctx) {
  MeshSet out;
  for (std::size_t i = 0; i < kInputs; ++i)
    if (ctx.has_input(i))
      for (const TaggedMesh& part : ctx.input<MeshSet>(i).parts) out.parts.push_back(part);
  ctx.set_output(0, std::move(out));
}

}  // namespace
PROCEX_REGISTER_NODE("Merge", 1, declare, evaluate);
}  // namespace procex
