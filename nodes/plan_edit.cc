// Plan Edit: steps inserted into the building's cross-section at an anchor
// (paper 3.5, 4.6, fig. 6, 20, 21; core/geom/plan_edit.h), each new edge
// following its own profile: bay windows and buttresses out of walls, dormers
// out of roofs, recesses and inverse dormers into them.
#include <sstream>
#include <stdexcept>

#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

enum Param : std::size_t { kKind, kWidth, kDepth, kSpread, kShape, kAngle, kTag, kCount, kSpacing };

void declare(NodeDecl& d) {
  d.doc("Inserts a step into the cross-section where the anchor `at` lies on each edge it selects, at its height: "
        "`natural` grows a protrusion `width` wide to `depth` out of the face (negative: a recess into it) from a "
        "vanishingly small one, so where it runs into the rest of the building it merges instead of crossing it; "
        "`forced` splices in the polyline `shape` (x along the edge from the anchor, y out of the face; first and "
        "last points on the edge), which may cross the building (the mesh then fails validation). The inserted "
        "edges follow `profile` from the step's height up (without one: they rise at `angle`). On the footprint "
        "(height 0) the step changes the footprint itself. `count` copies sit `spacing` apart along the edge, "
        "centred on the anchor. Where a step does not fit on an edge at its height, Extrude warns and skips it.")
      .category("Geometry");
  d.input<AnchorSpec>("at").doc("where (its name names the edit in warnings)");
  d.input<Profile>("profile").optional().doc("the profile of every inserted edge, starting at the step's height");
  d.param_enum("kind", {"natural", "forced"}).doc("grown (always a manifold) or spliced in as drawn");
  d.param<double>("width").default_value(2.0).range(0, 1000).unit("m").doc("natural: the step's width along the edge");
  d.param<double>("depth").default_value(1.0).range(-1000, 1000).unit("m")
      .doc("natural: how far it grows out of the face (negative: into the building)");
  d.param<double>("spread").default_value(0.0).range(-1000, 1000).unit("m")
      .doc("natural: how far each side moves out on the way (positive: wider at the front)");
  d.param<std::string>("shape").default_value(std::string("-1 0; -1 1; 1 1; 1 0"))
      .doc("forced: points `x y` separated by `;`, x along the edge from the anchor, y out of the face (metres)");
  d.param<double>("angle").default_value(0.0).range(-90, 90).unit("deg")
      .doc("without a profile: the inserted edges' angle from the vertical");
  d.param<std::string>("tag").default_value(std::string("step")).doc("tags the horizontal faces the step makes at its height");
  d.param<std::int64_t>("count").default_value<std::int64_t>(1).range(1, 1000).doc("copies side by side along the edge");
  d.param<double>("spacing").default_value(4.0).range(0, 10000).unit("m").doc("between the copies' centres");
  d.output<PlanEditSpec>("edit");
}

// "-1 0; -1 1; 1 1; 1 0" -> points; throws std::invalid_argument naming the bad item.
std::vector<glm::dvec2> parse_shape(const std::string& text) {
  std::vector<glm::dvec2> points;
  std::stringstream items(text);
  std::string item;
  for (int n = 1; std::getline(items, item, ';'); ++n) {
    std::istringstream in(item);
    glm::dvec2 p;
    std::string rest;
    if (!(in >> p.x >> p.y) || (in >> rest))
      throw std::invalid_argument("shape: point " + std::to_string(n) + " ('" + item +
                                  "') is not two numbers `x y`; write points as `x y` separated by `;`, e.g. "
                                  "'-1 0; -1 1; 1 1; 1 0'");
    points.push_back(p);
  }
  return points;
}

void evaluate(EvalContext& ctx) {
  PlanEditSpec spec;
  spec.at = ctx.input<AnchorSpec>(0);
  PlanEdit edit;
  edit.name = spec.at.anchor.name;
  edit.kind = ctx.choice_index(kKind) == 0 ? PlanEdit::Kind::Natural : PlanEdit::Kind::Forced;
  edit.tag = ctx.param<std::string>(kTag);
  std::size_t new_edges = 3;
  if (edit.kind == PlanEdit::Kind::Natural) {
    edit.width = ctx.param<double>(kWidth);
    edit.depth = ctx.param<double>(kDepth);
    edit.spread = ctx.param<double>(kSpread);
    if (!(edit.width > 0.0)) return ctx.error("width: a natural step needs a width above 0");
    if (edit.depth == 0.0) return ctx.error("depth: a natural step needs a depth (negative for a recess)");
  } else {
    try {
      edit.shape = parse_shape(ctx.param<std::string>(kShape));
    } catch (const std::invalid_argument& e) {
      return ctx.error(e.what());
    }
    if (edit.shape.size() < 2) return ctx.error("shape: a forced step needs at least two points");
    new_edges = edit.shape.size() - 1;
  }
  EdgeSpec inserted{ctx.param<double>(kAngle), -1, -1};
  if (ctx.has_input(1)) {
    spec.profiles.push_back(ctx.input<Profile>(1));
    inserted.profile = 0;
  }
  edit.edges.assign(new_edges, inserted);
  const auto count = ctx.param<std::int64_t>(kCount);
  const double spacing = ctx.param<double>(kSpacing);
  for (std::int64_t i = 0; i < count; ++i) {
    edit.offset = (static_cast<double>(i) - 0.5 * static_cast<double>(count - 1)) * spacing;
    spec.edits.push_back(edit);
  }
  ctx.set_output(0, std::move(spec));
}

}  // namespace
PROCEX_REGISTER_NODE("Plan Edit", 1, declare, evaluate);
}  // namespace procex
