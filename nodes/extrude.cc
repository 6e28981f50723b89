// Extrude: the sweep (paper 4) from a footprint to a closed, tagged mesh.
#include "core/mesh/validate.h"
#include "graph/registry.h"
#include "nodes/support/errors.h"
#include "nodes/support/extrusion.h"
#include "nodes/values.h"

namespace procex {
namespace {

void declare(NodeDecl& d) {
  d.doc("Sweeps a plane up from the footprint: every edge's face follows its profile (or leans at its angle), "
        "meeting faces are resolved into a closed 2-manifold. Faces are tagged by their profile segment's tag, "
        "else wall (vertical) or roof; the footprint face is tagged base, flat tops cap. Repairs of the footprint "
        "(merged vertices, fixed orientation) become warnings.")
      .category("Geometry");
  d.input<Footprint>("footprint");
  d.param<double>("max_height").default_value(0.0).range(0, 10000).unit("m")
      .doc("caps the sweep with flat faces at this height (0: no cap beyond the profiles' tops)");
  d.param_enum("ambiguity", {"maximize_volume", "minimize_volume"})
      .doc("how parallel edges that meet are resolved (paper 4.5)");
  d.param<bool>("validate").default_value(false)
      .doc("check the mesh (closed, manifold, oriented, planar, no self-intersection) and fail if it is not");
  d.output<MeshSet>("mesh");
}

void evaluate(EvalContext& ctx) {
  SweepOptions options;
  if (const double h = ctx.param<double>(0); h > 0) options.max_height = h;
  options.ambiguity = ctx.choice(1) == "minimize_volume" ? Ambiguity::MinimizeVolume : Ambiguity::MaximizeVolume;
  Extrusion result;
  try {
    result = extrude(ctx.input<Footprint>(0), options);
  } catch (const std::exception& e) {
    return ctx.error(describe(e));
  }
  for (const std::string& note : result.notes) ctx.warning(note);
  if (ctx.param<bool>(2)) {
    const ValidationReport v = validate(*result.mesh.mesh);
    if (!v.ok()) {
      std::string first = v.problems.empty() ? "no details" : v.problems.front();
      return ctx.error("the mesh does not validate (" + std::to_string(v.problems.size()) + " problems): " + first);
    }
  }
  ctx.set_output(0, MeshSet{{std::move(result.mesh)}});
}

}  // namespace
PROCEX_REGISTER_NODE("Extrude", 1, declare, evaluate);
}  // namespace procex
