// Footprint Shape: a parametric plan (rectangle, L, T, U, courtyard, n-gon).
#include <stdexcept>

#include "graph/registry.h"
#include "nodes/support/shapes.h"
#include "nodes/values.h"

namespace procex {
namespace {

void declare(NodeDecl& d) {
  d.doc("A parametric plan centred on the origin: rectangle, L, T or U plan, a courtyard (a rectangle with a "
        "rectangular hole) or a regular polygon (a circle with many sides). Edge ids run 0, 1, 2... "
        "counter-clockwise from the first corner, then round the hole.")
      .category("Footprint");
  d.param_enum("shape", {"rectangle", "l", "t", "u", "courtyard", "ngon"}).doc("the plan's shape");
  d.param<double>("width").default_value(12.0).range(0.1, 1000).unit("m").doc("extent along x (ngon: diameter)");
  d.param<double>("depth").default_value(10.0).range(0.1, 1000).unit("m").doc("extent along y");
  d.param<double>("arm").default_value(4.0).range(0.1, 500).unit("m")
      .doc("L, T, U: width of the arms; courtyard: thickness of the ring");
  d.param<std::int64_t>("sides").default_value<std::int64_t>(8).range(3, 256).doc("ngon: number of sides");
  d.param<double>("angle").default_value(45.0).range(-90, 90).unit("deg")
      .doc("every edge's slope from the vertical, for edges that get no profile (0 = wall)");
  d.output<Footprint>("footprint");
}

void evaluate(EvalContext& ctx) {
  ShapeSize size;
  size.width = ctx.param<double>(1);
  size.depth = ctx.param<double>(2);
  size.arm = ctx.param<double>(3);
  size.sides = static_cast<int>(ctx.param<std::int64_t>(4));
  try {
    ctx.set_output(0, make_footprint(make_shape(ctx.choice(0), size), ctx.param<double>(5)));
  } catch (const std::invalid_argument& e) {
    ctx.error(ctx.choice(0) + ": " + e.what());
  }
}

}  // namespace
PROCEX_REGISTER_NODE("Footprint Shape", 1, declare, evaluate);
}  // namespace procex
