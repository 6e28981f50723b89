// Footprint Polygon: a plan typed in as points.
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

void declare(NodeDecl& d) {
  d.doc("A plan given as its corners: the outer loop counter-clockwise, optionally one hole (clockwise). "
        "Orientation mistakes are repaired by Extrude. Edge ids run 0, 1, 2... along the outer loop, then the hole.")
      .category("Footprint");
  d.param<std::vector<Vec2>>("points")
      .default_value(std::vector<Vec2>{{0, 0}, {10, 0}, {10, 8}, {0, 8}})
      .unit("m")
      .doc("corners of the outer loop, x and y in metres");
  d.param<std::vector<Vec2>>("hole").default_value(std::vector<Vec2>{}).unit("m")
      .doc("corners of a hole (empty: none)");
  d.param<double>("angle").default_value(45.0).range(-90, 90).unit("deg")
      .doc("every edge's slope from the vertical, for edges that get no profile (0 = wall)");
  d.output<Footprint>("footprint");
}

std::vector<glm::dvec2> to_points(const std::vector<Vec2>& v) {
  std::vector<glm::dvec2> out;
  out.reserve(v.size());
  for (const Vec2& p : v) out.push_back({p.x, p.y});
  return out;
}

void evaluate(EvalContext& ctx) {
  const auto& outer = ctx.param<std::vector<Vec2>>(0);
  const auto& hole = ctx.param<std::vector<Vec2>>(1);
  if (outer.size() < 3) return ctx.error("points: a plan needs at least 3 corners, got " + std::to_string(outer.size()));
  if (!hole.empty() && hole.size() < 3) return ctx.error("hole: needs at least 3 corners (or none), got " + std::to_string(hole.size()));
  std::vector<std::vector<glm::dvec2>> loops = {to_points(outer)};
  if (!hole.empty()) loops.push_back(to_points(hole));
  ctx.set_output(0, make_footprint(loops, ctx.param<double>(2)));
}

}  // namespace
PROCEX_REGISTER_NODE("Footprint Polygon", 1, declare, evaluate);
}  // namespace procex
