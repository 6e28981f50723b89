// offset_edit.h -- Profile Offset nodes in the profile editor (paper 3.3,
// fig. 5): each steps every edge's profile sideways by `distance` at
// `height`, shown on the edited profile as a handle at the stepped point and
// dragged to edit both parameters.
#pragma once

#include <vector>

#include "graph/graph.h"

namespace procex::studio {

// The profile's offset at `height`: on its first segment that spans the
// height (the lower end of a horizontal run), below the first point its
// first offset, above the last point its last.
double profile_offset_at(const std::vector<Vec2>& profile, double height);

// A Profile Offset's step as a point of the profile editor: (offset of the
// profile at the height + distance, height).
Vec2 offset_handle(const std::vector<Vec2>& profile, double distance, double height);

// The parameters a handle dragged to `to` stands for, within the node's
// declared ranges: {distance, height}.
struct OffsetParams {
  double distance = 0, height = 0;
};
OffsetParams offset_params(const std::vector<Vec2>& profile, Vec2 to, const Node& profile_offset);

}  // namespace procex::studio
