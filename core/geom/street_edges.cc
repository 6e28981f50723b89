#include "core/geom/street_edges.h"

namespace procex {

std::vector<std::vector<std::int32_t>> street_edges(const std::vector<PlanLoops>& plans,
                                                    const std::vector<StreetLine>& streets, double distance) {
  const std::vector<PlanEdge> edges = plan_edges(plans);
  std::vector<LinePiece> pieces;
  for (std::size_t s = 0; s < streets.size(); ++s)
    for (std::size_t k = 0; k + 1 < streets[s].size(); ++k) pieces.push_back({streets[s][k], streets[s][k + 1], s});
  // In front of the edge, not behind the building.
  const LineTest in_front = [](const PlanEdge&, const LinePiece&, double outward, const void*) { return outward > 0; };
  return edges_along(plans.size(), edges, pieces, distance, in_front, nullptr);
}

}  // namespace procex
