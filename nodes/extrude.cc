// Extrude: the sweep (paper 4) from a footprint to a closed, tagged mesh.
#include "core/mesh/validate.h"
#include "graph/registry.h"
#include "nodes/support/errors.h"
#include "nodes/support/extrusion.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t max_height, ambiguity, validate, max_vertices, max_events, max_seconds;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("Sweeps a plane up from the footprint: every edge's face follows its profile (or leans at its angle), "
        "meeting faces are resolved into a closed 2-manifold. Faces are tagged by their profile segment's tag, "
        "else wall (vertical) or roof; the footprint face is tagged base, flat tops cap. Repairs of the footprint "
        "(merged vertices, fixed orientation) become warnings. Anchors (Anchor nodes on `anchor_k`) are resolved "
        "on the way up and carried on the mesh for Mesh Placement; where one is absent (its edge gone at its "
        "height) or selects no edge of this footprint, a warning says so. Plan edits (Plan Edit nodes on `edit_k`) "
        "are inserted into the cross-section at their heights; one that does not fit is skipped with a warning.")
      .category("Geometry");
  d.input<Footprint>("footprint");
  par.max_height = d.param<double>("max_height").default_value(0.0).range(0, 10000).unit("m")
      .doc("caps the sweep with flat faces at this height (0: no cap beyond the profiles' tops)").index();
  par.ambiguity = d.param_enum("ambiguity", {"maximize_volume", "minimize_volume"})
      .doc("how parallel edges that meet are resolved (paper 4.5)").index();
  par.validate = d.param<bool>("validate").default_value(false)
      .doc("check the mesh (closed, manifold, oriented, planar, no self-intersection) and fail if it is not").index();
  d.param<std::int64_t>("anchors").default_value<std::int64_t>(0).range(0, static_cast<double>(kMaxPortCount))
      .sets_port_count().doc("how many anchor inputs the node has");
  for (std::size_t i = 1; i <= d.count_of("anchors"); ++i)
    d.input<AnchorSpec>("anchor_" + std::to_string(i)).optional();
  d.param<std::int64_t>("plan_edits").default_value<std::int64_t>(0).range(0, static_cast<double>(kMaxPortCount))
      .sets_port_count().doc("how many plan edit inputs the node has");
  for (std::size_t i = 1; i <= d.count_of("plan_edits"); ++i)
    d.input<PlanEditSpec>("edit_" + std::to_string(i)).optional();
  // The budget: a footprint that makes the sweep run away fails with the
  // limit it passed instead of hanging the evaluation or exhausting memory.
  const SweepBudget budget;
  par.max_vertices = d.param<std::int64_t>("max_vertices")
      .default_value(static_cast<std::int64_t>(budget.max_vertices)).range(0, 1e12)
      .doc("refuse a footprint whose sweep makes more vertices, or more corners, or more events at one height, than "
           "this (it runs away; 0: no limit)")
      .index();
  par.max_events = d.param<std::int64_t>("max_events")
      .default_value(static_cast<std::int64_t>(budget.max_events)).range(0, 1e15)
      .doc("refuse a footprint whose sweep queues more potential events than this (0: no limit)").index();
  par.max_seconds = d.param<double>("max_seconds").default_value(budget.max_seconds).range(0, 1e6).unit("s")
      .doc("refuse a footprint whose sweep takes more CPU seconds than this (its thread's: the machine's load "
           "does not change the result; 0: no limit)").index();
  d.output<MeshSet>("mesh");
}

void evaluate(EvalContext& ctx) {
  SweepOptions options;
  if (const double h = ctx.param<double>(par.max_height); h > 0) options.max_height = h;
  options.ambiguity = ctx.choice(par.ambiguity) == "minimize_volume" ? Ambiguity::MinimizeVolume : Ambiguity::MaximizeVolume;
  options.budget.max_vertices = static_cast<std::size_t>(ctx.param<std::int64_t>(par.max_vertices));
  options.budget.max_events = static_cast<std::size_t>(ctx.param<std::int64_t>(par.max_events));
  options.budget.max_seconds = ctx.param<double>(par.max_seconds);
  std::vector<AnchorSpec> anchors;
  std::vector<PlanEditSpec> edits;
  for (std::size_t i = 1; i < ctx.decl().inputs().size(); ++i) {
    if (!ctx.has_input(i)) continue;
    if (ctx.decl().inputs()[i].name.starts_with("edit_"))
      edits.push_back(ctx.input<PlanEditSpec>(i));
    else
      anchors.push_back(ctx.input<AnchorSpec>(i));
  }
  Extrusion result;
  try {
    result = extrude(ctx.input<Footprint>(0), options, anchors, edits);
  } catch (const std::exception& e) {
    return ctx.error(describe(e));
  }
  for (const std::string& note : result.notes) ctx.warning(note);
  if (ctx.param<bool>(par.validate)) {
    const ValidationReport v = validate(*result.mesh.mesh, result.validation);
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
