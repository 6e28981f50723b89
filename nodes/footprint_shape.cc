// Footprint Shape: a parametric plan (rectangle, L, T, U, courtyard, n-gon).
#include <stdexcept>

#include "graph/registry.h"
#include "nodes/support/shapes.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t shape, width, depth, arm, sides, angle;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("A parametric plan centred on the origin: rectangle, L, T or U plan, a courtyard (a rectangle with a "
        "rectangular hole) or a regular polygon (a circle with many sides). Edge ids run 0, 1, 2... "
        "counter-clockwise from the first corner, then round the hole.")
      .category("Footprint");
  par.shape = d.param_enum("shape", {"rectangle", "l", "t", "u", "courtyard", "ngon"}).doc("the plan's shape").index();
  par.width = d.param<double>("width").default_value(12.0).range(0.1, 1000).unit("m").doc("extent along x (ngon: diameter)").index();
  par.depth = d.param<double>("depth").default_value(10.0).range(0.1, 1000).unit("m").doc("extent along y").index();
  par.arm = d.param<double>("arm").default_value(4.0).range(0.1, 500).unit("m")
      .doc("L, T, U: width of the arms; courtyard: thickness of the ring").index();
  par.sides = d.param<std::int64_t>("sides").default_value<std::int64_t>(8).range(3, 256).doc("ngon: number of sides").index();
  par.angle = d.param<double>("angle").default_value(45.0).range(-90, 90).unit("deg")
      .doc("every edge's slope from the vertical, for edges that get no profile (0 = wall)").index();
  d.output<Footprint>("footprint");
}

void evaluate(EvalContext& ctx) {
  ShapeSize size;
  size.width = ctx.param<double>(par.width);
  size.depth = ctx.param<double>(par.depth);
  size.arm = ctx.param<double>(par.arm);
  size.sides = static_cast<int>(ctx.param<std::int64_t>(par.sides));
  try {
    ctx.set_output(0, make_footprint(make_shape(ctx.choice(par.shape), size), ctx.param<double>(par.angle)));
  } catch (const std::invalid_argument& e) {
    ctx.error(ctx.choice(par.shape) + ": " + e.what());
  }
}

}  // namespace
PROCEX_REGISTER_NODE("Footprint Shape", 1, declare, evaluate);
}  // namespace procex
