#include "core/geom/round_edge.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/geom/tolerances.h"

namespace procex {

std::optional<std::vector<std::size_t>> twins_round_edge(const glm::dvec3& axis, std::span<const FaceAtEdge> faces) {
  if (faces.empty()) return std::nullopt;
  const glm::dvec3 unit = glm::normalize(axis);
  // Each face leaves the edge to the left of its boundary seen from outside;
  // that direction's angle round the axis orders the faces.
  auto leaving = [&](const FaceAtEdge& f) { return glm::cross(f.normal, f.along ? unit : -unit); };
  const glm::dvec3 ref = glm::normalize(leaving(faces[0]) - unit * glm::dot(leaving(faces[0]), unit));
  const glm::dvec3 ref_turned = glm::cross(unit, ref);
  std::vector<std::pair<double, std::size_t>> round;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const glm::dvec3 d = leaving(faces[i]);
    round.push_back({std::atan2(glm::dot(d, ref_turned), glm::dot(d, ref)), i});
  }
  std::sort(round.begin(), round.end());
  // Two faces leaving the same way (to rounding) overlap there, whichever
  // order rounding gives them.
  std::vector<std::size_t> twin(faces.size());
  for (std::size_t k = 0; k < round.size(); ++k) {
    const auto& [angle, a] = round[k];
    const auto& [next_angle, b] = round[(k + 1) % round.size()];
    const double gap = k + 1 < round.size() ? next_angle - angle : next_angle + 2.0 * M_PI - angle;
    if (faces[a].along == faces[b].along || !(gap > kSameWayAngle)) return std::nullopt;
    if (!faces[a].along) twin[a] = b, twin[b] = a;
  }
  return twin;
}

}  // namespace procex
