// Profile Preset: the common profiles, by name and a few sizes.
#include <stdexcept>

#include "graph/registry.h"
#include "nodes/support/profile_presets.h"
#include "nodes/values.h"

namespace procex {
namespace {

void declare(NodeDecl& d) {
  d.doc("A ready-made profile. vertical_wall: a wall `height` high (tag wall). hip: a roof slope at `pitch` "
        "rising up to `roof_height` (roof). gable_end: a vertical face up to `roof_height` that the other "
        "slopes close over (gable). mansard: a steep slope for `height`, then `pitch` (roof, roof). "
        "overhanging_eave: a wall, an eave reaching `overhang` out, then a roof slope (wall, soffit, roof). "
        "curved: a quarter circle of radius `roof_height` in `segments` pieces (roof). overhanging_gable: the "
        "verge of a gable wall beside overhanging_eave edges: a wall, a soffit `overhang` out, then a vertical "
        "gable `roof_height` high (wall, soffit, gable). setback: tiers `height` high, each stepping in by "
        "`overhang`, up to `roof_height` (wall, ledge, wall, ...).")
      .category("Profile");
  d.param_enum("preset", preset_names()).doc("which profile (see above)");
  d.param<double>("height").default_value(3.0).range(0.01, 1000).unit("m").doc("wall height, or the mansard's lower slope");
  d.param<double>("pitch").default_value(45.0).range(-89, 89).unit("deg").doc("roof slope from the vertical");
  d.param<double>("roof_height").default_value(30.0).range(0.01, 1000).unit("m")
      .doc("highest a roof rises; the sweep caps it flat there");
  d.param<double>("overhang").default_value(0.5).range(0.01, 10).unit("m").doc("overhanging_eave, overhanging_gable: eave depth; setback: the step");
  d.param<std::int64_t>("segments").default_value<std::int64_t>(6).range(1, 64).doc("curved: pieces of the arc");
  d.output<Profile>("profile");
}

void evaluate(EvalContext& ctx) {
  PresetSize s;
  s.height = ctx.param<double>(1);
  s.pitch_deg = ctx.param<double>(2);
  s.roof_height = ctx.param<double>(3);
  s.overhang = ctx.param<double>(4);
  s.segments = static_cast<int>(ctx.param<std::int64_t>(5));
  try {
    ctx.set_output(0, make_preset(ctx.choice(0), s));
  } catch (const std::invalid_argument& e) {
    ctx.error(ctx.choice(0) + ": " + e.what());
  }
}

}  // namespace
PROCEX_REGISTER_NODE("Profile Preset", 1, declare, evaluate);
}  // namespace procex
