#include "core/geom/party_walls.h"

#include <glm/geometric.hpp>

namespace procex {

std::vector<std::vector<std::int32_t>> party_edges(const std::vector<PlanLoops>& plans, double distance) {
  const std::vector<PlanEdge> edges = plan_edges(plans);
  std::vector<LinePiece> walls;
  walls.reserve(edges.size());
  for (std::size_t j = 0; j < edges.size(); ++j) walls.push_back({edges[j].a, edges[j].b, j});
  // Another plan's edge whose outward side meets this one's (the same plan
  // twice in a file shares nothing with itself).
  const LineTest neighbour = [](const PlanEdge& e, const LinePiece& wall, double, const void* context) {
    const PlanEdge& f = (*static_cast<const std::vector<PlanEdge>*>(context))[wall.owner];
    return f.plan != e.plan && glm::dot(e.out, f.out) < 0;
  };
  return edges_along(plans.size(), edges, walls, distance, neighbour, &edges);
}

}  // namespace procex
