#include "tests/support/tangential_skeleton.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include <glm/geometric.hpp>

#include "tests/support/roof_properties.h"

namespace procex::testing {

std::optional<CgalSkeleton> tangential_skeleton(const Footprint& footprint) {
  if (footprint.loops.size() != 1) return std::nullopt;
  const Loop& loop = footprint.loops[0];
  const std::size_t n = loop.points.size();
  if (n < 3) return std::nullopt;
  const glm::dvec2 centre = std::accumulate(loop.points.begin(), loop.points.end(), glm::dvec2(0.0)) / double(n);
  const double within = 1e-9 * plan_diagonal(footprint);
  // The centre's distance from each edge's line, positive on its inner
  // (left, the loop running counter-clockwise) side.
  double r = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = loop.points[i], d = loop.points[(i + 1) % n] - a;
    const double length = glm::length(d);
    if (!(length > 0.0)) return std::nullopt;
    const glm::dvec2 c = centre - a;
    const double distance = (d.x * c.y - d.y * c.x) / length;
    if (i == 0) r = distance;
    if (!(distance > within) || std::abs(distance - r) > within) return std::nullopt;
  }
  CgalSkeleton out;
  out.nodes.push_back({centre.x, centre.y, r});
  for (std::size_t i = 0; i < n; ++i) {
    // The bisector from corner i, between edges i - 1 and i, to the node.
    const std::int32_t a = loop.edges[(i + n - 1) % n].id, b = loop.edges[i].id;
    out.ridges.push_back({std::min(a, b), std::max(a, b), glm::dvec3(loop.points[i], 0.0), out.nodes[0]});
    out.faces_per_edge.emplace_back(b, 1);
  }
  std::sort(out.ridges.begin(), out.ridges.end(),
            [](const CgalRidge& x, const CgalRidge& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
  std::sort(out.faces_per_edge.begin(), out.faces_per_edge.end());
  return out;
}

}  // namespace procex::testing
