// Levels: a profile's wall made a number of floors high, the rest of the
// profile (eaves, roof, a party wall's top) carried up with it, so a wall
// height can follow a feature's `building:levels` while the roof keeps the
// shape its points draw.
#include <string>

#include "core/geom/error.h"
#include "core/geom/profile.h"
#include "graph/registry.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t profile_in, levels, floor_height, profile_out;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("Makes a profile's wall `levels` floors of `floor_height` high: the profile's first segment (its wall, "
        "which must be vertical) ends at levels x floor_height, and every point above it moves up by the same "
        "amount, so the roof keeps its shape. `levels` may be an expression of the feature's attributes, "
        "e.g. attr(\"building:levels\", 2) (docs/expressions.md); a Facade Split with floors of the same height "
        "then finds one floor per level.")
      .category("Profile");
  par.profile_in = d.input<Profile>("profile").index();
  par.levels = d.param<std::int64_t>("levels").default_value<std::int64_t>(2).range(1, 1000).doc("floors in the wall").index();
  par.floor_height = d.param<double>("floor_height").default_value(3.0).range(0.1, 100).unit("m").doc("each floor's height").index();
  par.profile_out = d.output<Profile>("profile").index();
}

void evaluate(EvalContext& ctx) {
  Profile p = ctx.input<Profile>(par.profile_in);
  if (p.points.size() < 2 || p.points[1].x != p.points[0].x)
    return ctx.error("profile '" + p.name + "': its first segment is not a vertical wall, so it has no wall to make " +
                     "levels high (draw it from (0, 0) straight up)");
  const double wall = static_cast<double>(ctx.param<std::int64_t>(par.levels)) * ctx.param<double>(par.floor_height);
  const double raise = wall - p.points[1].y;
  for (std::size_t i = 1; i < p.points.size(); ++i) p.points[i].y += raise;
  try {
    check_profile(p);
  } catch (const InputError& e) {
    return ctx.error(e.what());
  }
  ctx.set_output(par.profile_out, std::move(p));
}

}  // namespace
PROCEX_REGISTER_NODE("Levels", 1, declare, evaluate);
}  // namespace procex
