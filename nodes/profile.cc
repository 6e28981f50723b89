// Profile: a cross-section polyline with a tag per segment (paper 3.2).
#include "core/geom/error.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t name, points, tags;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("A profile: the path an edge's face follows as the sweep rises, as points (outward offset, height) "
        "starting at (0, 0) and never going down; x < 0 leans inward. Each segment's tag names the faces it makes.")
      .category("Profile");
  par.name = d.param<std::string>("name").default_value(std::string("profile")).doc("how Assign Profiles rules refer to it").index();
  par.points = d.param<std::vector<Vec2>>("points")
      .default_value(std::vector<Vec2>{{0, 0}, {0, 3}, {-3, 6}})
      .unit("m")
      .doc("(outward offset, height) pairs, the first (0, 0)").index();
  par.tags = d.param<std::vector<std::string>>("tags")
      .default_value(std::vector<std::string>{"wall", "roof"})
      .doc("one per segment (may be empty: walls and roofs are then told apart by slope)").index();
  d.output<Profile>("profile");
}

void evaluate(EvalContext& ctx) {
  Profile p;
  p.name = ctx.param<std::string>(par.name);
  for (const Vec2& q : ctx.param<std::vector<Vec2>>(par.points)) p.points.push_back({q.x, q.y});
  p.tags = ctx.param<std::vector<std::string>>(par.tags);
  try {
    check_profile(p);
  } catch (const InputError& e) {
    return ctx.error(e.what());
  }
  ctx.set_output(0, std::move(p));
}

}  // namespace
PROCEX_REGISTER_NODE("Profile", 1, declare, evaluate);
}  // namespace procex
