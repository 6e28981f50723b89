// Profile Preset: the common profiles, by name and a few sizes.
#include <stdexcept>

#include "graph/registry.h"
#include "nodes/support/profile_presets.h"
#include "nodes/values.h"

namespace procex {
namespace {

// Parameter handles, from the declaration.
struct Params {
  std::size_t preset, height, pitch, roof_height, overhang, segments;
};
Params par;

void declare(NodeDecl& d) {
  d.doc("A ready-made profile. vertical_wall: a wall `height` high (tag wall). hip: a roof slope at `pitch` "
        "rising up to `roof_height` (roof). gable_end: a vertical face up to `roof_height` that the other "
        "slopes close over (gable). mansard: a steep slope for `height`, then `pitch` (roof, roof). "
        "overhanging_eave: a wall, an eave reaching `overhang` out, then a roof slope (wall, soffit, roof). "
        "curved: a quarter circle of radius `roof_height` in `segments` pieces (roof). overhanging_gable: the "
        "verge of a gable wall beside overhanging_eave edges: a wall, a soffit `overhang` out, then a vertical "
        "gable `roof_height` high (wall, soffit, gable). setback: tiers `height` high, each stepping in by "
        "`overhang`, up to `roof_height` (wall, ledge, wall, ...). flush_eave: a wall `height` high, then a roof slope "
        "at `pitch` rising `roof_height` more, flush with the wall (wall, roof), for Roof Overhang to run out.")
      .category("Profile");
  par.preset = d.param_enum("preset", preset_names()).doc("which profile (see above)").index();
  par.height = d.param<double>("height").default_value(3.0).range(0.01, 1000).unit("m").doc("wall height, or the mansard's lower slope").index();
  par.pitch = d.param<double>("pitch").default_value(45.0).range(-89, 89).unit("deg").doc("roof slope from the vertical").index();
  par.roof_height = d.param<double>("roof_height").default_value(30.0).range(0.01, 1000).unit("m")
      .doc("highest a roof rises; the sweep caps it flat there").index();
  par.overhang = d.param<double>("overhang").default_value(0.5).range(0.01, 10).unit("m").doc("overhanging_eave, overhanging_gable: eave depth; setback: the step").index();
  par.segments = d.param<std::int64_t>("segments").default_value<std::int64_t>(6).range(1, 64).doc("curved: pieces of the arc").index();
  d.output<Profile>("profile");
}

void evaluate(EvalContext& ctx) {
  PresetSize s;
  s.height = ctx.param<double>(par.height);
  s.pitch_deg = ctx.param<double>(par.pitch);
  s.roof_height = ctx.param<double>(par.roof_height);
  s.overhang = ctx.param<double>(par.overhang);
  s.segments = static_cast<int>(ctx.param<std::int64_t>(par.segments));
  try {
    ctx.set_output(0, make_preset(ctx.choice(par.preset), s));
  } catch (const std::invalid_argument& e) {
    ctx.error(ctx.choice(par.preset) + ": " + e.what());
  }
}

}  // namespace
PROCEX_REGISTER_NODE("Profile Preset", 1, declare, evaluate);
}  // namespace procex
