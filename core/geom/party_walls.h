// Party walls: the edges of a footprint that run along an edge of a
// neighbouring footprint (terraced houses, Manhattan lots), so a recipe can
// give them a blank vertical wall instead of windows and eaves (issue 15).
#pragma once

#include <cstdint>
#include <vector>

#include "core/geom/edges_along.h"

namespace procex {

// For each plan, the ids of its edges (numbered 0, 1, 2, ... across its loops
// in order, as to_footprint numbers them) of which at least half the length
// lies within `distance` of edges of other plans that run along it (parallel
// to within 10 degrees) and face it: their outward sides meet, as a wall
// between two buildings has (the same plan twice in a file shares nothing).
// Sorted.
std::vector<std::vector<std::int32_t>> party_edges(const std::vector<PlanLoops>& plans, double distance);

}  // namespace procex
