#include "nodes/support/profile_presets.h"

#include <cmath>
#include <stdexcept>

namespace procex {
namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// The inward run of a slope pitched `pitch_deg` from the vertical over `rise`.
double inward(double pitch_deg, double rise) { return rise * std::tan(pitch_deg * M_PI / 180.0); }

}  // namespace

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> kNames = {"vertical_wall", "hip", "gable_end", "mansard", "overhanging_eave",
                                                  "curved",        "overhanging_gable", "setback", "flush_eave"};
  return kNames;
}

Profile make_preset(std::string_view preset, const PresetSize& s) {
  require(s.height > 0, "height must be positive");
  require(s.roof_height > 0, "roof_height must be positive");
  require(s.pitch_deg > -90 && s.pitch_deg < 90, "pitch must lie strictly between -90 and 90 degrees");
  const std::string name(preset);
  if (preset == "vertical_wall") return {name, {{0, 0}, {0, s.height}}, {"wall"}};
  if (preset == "hip") return {name, {{0, 0}, {-inward(s.pitch_deg, s.roof_height), s.roof_height}}, {"roof"}};
  // A gable end rises vertically until the roof slopes from the other edges close over it.
  if (preset == "gable_end") return {name, {{0, 0}, {0, s.roof_height}}, {"gable"}};
  if (preset == "mansard") {
    // A steep lower slope (a fifth of the pitch from the vertical) for `height`, then the pitch.
    require(s.roof_height > s.height, "mansard: roof_height must exceed height (the lower slope)");
    const double x1 = -inward(s.pitch_deg / 5, s.height);
    return {name, {{0, 0}, {x1, s.height}, {x1 - inward(s.pitch_deg, s.roof_height - s.height), s.roof_height}},
            {"roof", "roof"}};
  }
  if (preset == "flush_eave") {
    // A wall and its roof with no overhang: Roof Overhang runs the roof out past the wall.
    return {name, {{0, 0}, {0, s.height}, {-inward(s.pitch_deg, s.roof_height), s.height + s.roof_height}}, {"wall", "roof"}};
  }
  if (preset == "overhanging_eave") {
    require(s.overhang > 0, "overhanging_eave: overhang must be positive");
    const double top = s.height + s.roof_height;
    return {name,
            {{0, 0}, {0, s.height}, {s.overhang, s.height}, {s.overhang - inward(s.pitch_deg, s.roof_height), top}},
            {"wall", "soffit", "roof"}};
  }
  if (preset == "overhanging_gable") {
    // The verge over a gable wall: out by the eaves' overhang at their height, so the roof planes of the
    // overhanging_eave edges meet it there.
    require(s.overhang > 0, "overhanging_gable: overhang must be positive");
    return {name, {{0, 0}, {0, s.height}, {s.overhang, s.height}, {s.overhang, s.height + s.roof_height}},
            {"wall", "soffit", "gable"}};
  }
  if (preset == "setback") {
    // Tiers `height` high, each stepping in by `overhang`, up to `roof_height`, where the sweep caps it.
    require(s.overhang > 0, "setback: overhang (the step) must be positive");
    require(s.roof_height <= 1000 * s.height, "setback: more than 1000 tiers");
    Profile p{name, {{0, 0}}, {}};
    double x = 0, z = 0;
    while (z + s.height < s.roof_height * (1 - 1e-9)) {
      z += s.height;
      p.points.push_back({x, z});
      x -= s.overhang;
      p.points.push_back({x, z});
      p.tags.insert(p.tags.end(), {"wall", "ledge"});
    }
    p.points.push_back({x, s.roof_height});
    p.tags.push_back("wall");
    return p;
  }
  if (preset == "curved") {
    // A quarter circle of radius roof_height bending inward from vertical to flat.
    require(s.segments >= 1 && s.segments <= 64, "curved: segments must be 1 to 64");
    Profile p{name, {{0, 0}}, {}};
    const double r = s.roof_height;
    for (int i = 1; i <= s.segments; ++i) {
      const double a = M_PI / 2 * i / s.segments;
      p.points.push_back({-(r - r * std::cos(a)), r * std::sin(a)});
      p.tags.push_back("roof");
    }
    return p;
  }
  throw std::invalid_argument("unknown preset '" + name + "'");
}

}  // namespace procex
