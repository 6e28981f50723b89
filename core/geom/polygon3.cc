#include "core/geom/polygon3.h"

#include <cmath>

namespace procex {

glm::dvec3 newell_normal(const std::vector<glm::dvec3>& points) {
  glm::dvec3 n{0.0};
  const std::size_t count = points.size();
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3& a = points[i];
    const glm::dvec3& b = points[(i + 1) % count];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

void drop_axis(const std::vector<glm::dvec3>& points, const glm::dvec3& normal, std::vector<glm::dvec2>& out) {
  const glm::dvec3 a{std::abs(normal.x), std::abs(normal.y), std::abs(normal.z)};
  // Axes (u, v) with u x v along +normal's dominant axis: (y, z) for x,
  // (z, x) for y, (x, y) for z; swapped when that component is negative.
  int u = 0, v = 1;
  double sign = normal.z;
  if (a.x >= a.y && a.x >= a.z) {
    u = 1, v = 2, sign = normal.x;
  } else if (a.y >= a.z) {
    u = 2, v = 0, sign = normal.y;
  }
  if (sign < 0) std::swap(u, v);
  out.clear();
  out.reserve(points.size());
  for (const glm::dvec3& p : points) out.push_back({p[u], p[v]});
}

std::vector<glm::dvec2> drop_axis(const std::vector<glm::dvec3>& points, const glm::dvec3& normal) {
  std::vector<glm::dvec2> out;
  drop_axis(points, normal, out);
  return out;
}

}  // namespace procex
