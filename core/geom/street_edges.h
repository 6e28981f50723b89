// Street edges: the edges of a footprint that face a street line (a road's
// centre line from the same file or another), so Assign Profiles can label the
// building's front by data rather than by its longest edge (issue 15).
#pragma once

#include <cstdint>
#include <vector>

#include "core/geom/edges_along.h"

namespace procex {

// A street's centre line, as read (a LineString).
using StreetLine = std::vector<glm::dvec2>;

// For each plan, the ids of its edges (as party_edges numbers them) of which at
// least half the length lies within `distance` of streets that run along it
// (parallel to within 10 degrees) on its outer side. Sorted.
std::vector<std::vector<std::int32_t>> street_edges(const std::vector<PlanLoops>& plans,
                                                    const std::vector<StreetLine>& streets, double distance);

}  // namespace procex
