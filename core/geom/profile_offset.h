// Profile offsets (paper 3.3, fig. 5): one point (distance, height) shared by
// every edge's profile. At that height each edge steps sideways by the
// distance (outward positive: a soffit; inward: a ledge) and its profile
// carries on from the step, so editing the one offset moves where every roof
// starts. Single edges, chosen by their profile's name or their edge id, may
// take their own distance, continue above the offset with their own slope, or
// drop out of the offset (no step). The offset is a rewrite of each edge's
// profile, defined per profile and edge, never by coordinates: it stays valid
// when the footprint changes. The sweep then makes the steps (horizontal
// runs, core/sweep/horizontal_event.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/geom/footprint.h"

namespace procex {

// Which edges an override applies to, and what it changes for them.
struct OffsetOverride {
  std::string profile;                // edges whose profile has this name ...
  std::vector<std::int32_t> edge_ids;  // ... or these EdgeSpec ids (either may be empty, not both)
  std::optional<double> distance;      // their own step (m, outward positive)
  std::optional<double> slope_deg;     // their own angle above the offset, from the vertical (positive leans in)
  bool drop = false;                   // no step: the profile stays as it is
};

struct ProfileOffset {
  std::string name;        // names the offset in errors ("offset 1", a node's name)
  double height = 3.0;     // where the step is (m, above the footprint)
  double distance = 0.5;   // the step (m, outward positive)
  std::string tag;         // the step's faces; empty: "soffit" outward, "ledge" inward
  std::vector<OffsetOverride> overrides;  // in order; a later one wins where two set the same thing
};

// Rewrites the profile of every edge the offsets reach: below the offset's
// height the profile is unchanged (a segment crossing it is split there),
// then a horizontal segment of the edge's distance, then the profile's part
// above, moved to start at the end of the step (or one segment at the edge's
// own slope, rising to the profile's top or until a roof at that slope has
// surely closed over the footprint, whichever is higher: Extrude caps a
// building at its profiles' tops). An edge without a profile follows its
// constant angle, up to where it has surely closed. Offsets
// apply from the lowest up, so several at different heights compose. Edges
// with equal rewritten profiles share one; a rewritten profile keeps its
// original's name, so later offsets select it by that name.
// Throws InputError naming the offset (and override) for a height or distance
// that is not a finite number, a height not above 0, a slope outside
// (-90, 90), an unknown profile name or edge id, and an override that selects
// nothing or changes nothing.
Footprint apply_profile_offsets(const Footprint& footprint, const std::vector<ProfileOffset>& offsets);

}  // namespace procex
