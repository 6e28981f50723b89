// Footprint Polygon: a plan typed in as points.
#include <nlohmann/json.hpp>

#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t points, holes, angle;
};
Params par;

using Loops = std::vector<std::vector<Vec2>>;

// Version 1 had one hole, `hole` (empty: none).
void upgrade(int saved_version, nlohmann::json& params) {
  if (saved_version >= 2) return;
  auto hole = params.find("hole");
  if (hole == params.end()) return;
  nlohmann::json holes = nlohmann::json::array();
  if (!hole->is_array() || !hole->empty()) holes.push_back(*hole);  // a malformed hole is reported by name when read
  params.erase(hole);
  params["holes"] = std::move(holes);
}

void declare(NodeDecl& d) {
  d.doc("A plan given as its corners: the outer loop counter-clockwise, and any number of holes (clockwise). "
        "Orientation mistakes are repaired by Extrude. Edge ids run 0, 1, 2... along the outer loop, then round "
        "each hole in turn.")
      .category("Footprint");
  par.points = d.param<std::vector<Vec2>>("points")
      .default_value(std::vector<Vec2>{{0, 0}, {10, 0}, {10, 8}, {0, 8}})
      .unit("m")
      .doc("corners of the outer loop, x and y in metres").index();
  par.holes = d.param<Loops>("holes").default_value(Loops{}).unit("m")
      .doc("the holes (courtyards), each a list of corners, e.g. [[[2, 2], [2, 4], [4, 4], [4, 2]]] (empty: none)").index();
  par.angle = d.param<double>("angle").default_value(45.0).range(-90, 90).unit("deg")
      .doc("every edge's slope from the vertical, for edges that get no profile (0 = wall)").index();
  d.output<Footprint>("footprint");
  d.upgrade(upgrade);
}

std::vector<glm::dvec2> to_points(const std::vector<Vec2>& v) {
  std::vector<glm::dvec2> out;
  out.reserve(v.size());
  for (const Vec2& p : v) out.push_back({p.x, p.y});
  return out;
}

void evaluate(EvalContext& ctx) {
  const auto& outer = ctx.param<std::vector<Vec2>>(par.points);
  const auto& holes = ctx.param<Loops>(par.holes);
  if (outer.size() < 3) return ctx.error("points: a plan needs at least 3 corners, got " + std::to_string(outer.size()));
  std::vector<std::vector<glm::dvec2>> loops = {to_points(outer)};
  for (std::size_t i = 0; i < holes.size(); ++i) {
    if (holes[i].size() < 3)
      return ctx.error("holes: hole " + std::to_string(i + 1) + " needs at least 3 corners, got " + std::to_string(holes[i].size()));
    loops.push_back(to_points(holes[i]));
  }
  ctx.set_output(0, make_footprint(loops, ctx.param<double>(par.angle)));
}

}  // namespace
PROCEX_REGISTER_NODE("Footprint Polygon", 2, declare, evaluate);
}  // namespace procex
