// Checking and repairing a footprint before the sweep. Repairs that cannot
// change the intended shape are made with a note (near-coincident consecutive
// vertices merged, loop orientation fixed to match nesting); anything else is
// refused with an InputError naming the loop and vertex.
#pragma once

#include <string>
#include <vector>

#include "core/geom/footprint.h"

namespace procex {

struct PreparedFootprint {
  Footprint footprint;             // ready for sweep()
  std::vector<std::string> notes;  // one line per repair, naming loop and vertex
};

// Refuses (InputError): a loop whose points and edges differ in count, NaN or
// infinite coordinates, coordinates beyond kMaxCoordinate, angles that are NaN or outside [-90, 90], a loop with
// fewer than 3 distinct vertices or zero area, a self-intersecting or
// self-touching loop, two loops that cross or touch.
// Repairs: consecutive vertices closer than merge_distance() are merged (the
// edge between them dropped); loops are reoriented so that loops at even
// nesting depth run counter-clockwise and loops at odd depth clockwise
// (depth = number of other loops containing it), keeping each edge's spec.
PreparedFootprint prepare_footprint(const Footprint& footprint);

}  // namespace procex
