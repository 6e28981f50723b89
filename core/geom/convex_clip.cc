#include "core/geom/convex_clip.h"

#include <glm/geometric.hpp>

namespace procex {

void clip_to_half_plane(const std::vector<glm::dvec2>& polygon, glm::dvec2 normal, double offset, double margin,
                        std::vector<glm::dvec2>& out) {
  out.clear();
  const double slack = margin * glm::length(normal);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    const double da = glm::dot(normal, a) + offset, db = glm::dot(normal, b) + offset;
    if (da >= -slack) out.push_back(a);
    if ((da > slack && db < -slack) || (da < -slack && db > slack)) out.push_back(a + da / (da - db) * (b - a));
  }
}

std::vector<glm::dvec2> clip_to_half_plane(const std::vector<glm::dvec2>& polygon, glm::dvec2 normal, double offset,
                                           double margin) {
  std::vector<glm::dvec2> out;
  clip_to_half_plane(polygon, normal, offset, margin, out);
  return out;
}

std::vector<glm::dvec2> clip_to_convex(std::vector<glm::dvec2> polygon, const std::vector<glm::dvec2>& window,
                                       double margin) {
  for (std::size_t i = 0; i < window.size() && !polygon.empty(); ++i) {
    const glm::dvec2 u = window[i], d = window[(i + 1) % window.size()] - u;
    // Left of u -> u + d: cross(d, p - u) >= 0.
    polygon = clip_to_half_plane(polygon, {-d.y, d.x}, d.y * u.x - d.x * u.y, margin);
  }
  return polygon;
}

}  // namespace procex
