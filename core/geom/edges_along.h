// Which footprint edges run along given lines: a neighbour's wall (party walls,
// party_walls.h) or a street (street_edges.h). Lines are found near each edge
// through a grid, so the cost grows with the lines near an edge, not with all
// pairs.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

// The loops of one footprint, as read (any orientation).
using PlanLoops = std::vector<std::vector<glm::dvec2>>;

// One footprint edge with its outward normal (from the loops' nesting, whatever
// their orientation) and its id (0, 1, 2, ... across the plan's loops in order,
// as to_footprint numbers them).
struct PlanEdge {
  glm::dvec2 a, b;
  glm::dvec2 out;  // unit
  std::size_t plan = 0;
  std::int32_t id = -1;
};

// Every edge of every plan of non-zero, finite length.
std::vector<PlanEdge> plan_edges(const std::vector<PlanLoops>& plans);

// A straight piece of a line (a footprint edge, a street), and what it belongs to.
struct LinePiece {
  glm::dvec2 a, b;
  std::size_t owner = 0;
};

// Decides whether a piece counts for edge `e` (a neighbour's wall facing it, a
// street on its outer side). `outward`: how far the piece lies out from e,
// along e.out, midway over the span of e it runs along.
using LineTest = bool (*)(const PlanEdge& e, const LinePiece& piece, double outward, const void* context);

// For each of `plans` plans, the ids of its edges of which at least half the
// length lies within `distance` of pieces that run along them (parallel to
// within 10 degrees) and pass `counts`. Sorted.
std::vector<std::vector<std::int32_t>> edges_along(std::size_t plans, const std::vector<PlanEdge>& edges,
                                                   const std::vector<LinePiece>& pieces, double distance,
                                                   LineTest counts, const void* context);

}  // namespace procex
