// The preset profiles of the Profile Preset node (paper fig. 3 and 22): each
// a polyline in (outward offset, height) with a tag per segment.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/geom/profile.h"

namespace procex {

struct PresetSize {
  double height = 3.0;        // wall height (vertical_wall, overhanging_eave) or the mansard's lower slope
  double pitch_deg = 45.0;    // roof slope, degrees from the vertical
  double roof_height = 30.0;  // how far a roof may rise before the sweep caps it flat
  double overhang = 0.5;      // overhanging_eave: how far the eave reaches out
  int segments = 6;           // curved: segments of the quarter circle
};

// The names, in the order the node offers them.
const std::vector<std::string>& preset_names();

// Throws std::invalid_argument naming the parameter when the sizes make no
// valid profile; the result passes check_profile().
Profile make_preset(std::string_view preset, const PresetSize& size);

}  // namespace procex
