// Points sorted by x, so that finding a neighbour within a tolerance is a
// binary search: how the oracle and the property checks match two roofs'
// vertices.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/vec3.hpp>

namespace procex::testing {

class PointSet {
 public:
  explicit PointSet(std::vector<glm::dvec3> points) : points_(std::move(points)) {
    std::sort(points_.begin(), points_.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  }
  // Distance to the nearest point among those within tol in x; +inf if none.
  double nearest(const glm::dvec3& p, double tol) const {
    auto it = std::lower_bound(points_.begin(), points_.end(), p.x - tol,
                               [](const glm::dvec3& a, double x) { return a.x < x; });
    double best = std::numeric_limits<double>::infinity();
    for (; it != points_.end() && it->x <= p.x + tol; ++it) {
      const glm::dvec3 d = *it - p;
      best = std::min(best, std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z));
    }
    return best;
  }

 private:
  std::vector<glm::dvec3> points_;
};

}  // namespace procex::testing
