// A mesh seen from above, for the level-of-detail tests: the area its faces
// cover facing up and facing down, and the heights they span.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geom/polygon3.h"
#include "core/mesh/mesh.h"

namespace procex::test {

struct Plan {
  double up_area = 0.0, down_area = 0.0, low = INFINITY, high = -INFINITY;
};

inline Plan plan_of(const Mesh& m) {
  Plan p;
  for (const auto f : m.faces()) {
    std::vector<glm::dvec3> pts;
    for (const auto v : m.fv_range(f)) {
      const auto& q = m.point(v);
      pts.emplace_back(q[0], q[1], q[2]);
      p.low = std::min(p.low, q[2]);
      p.high = std::max(p.high, q[2]);
    }
    const double z = newell_normal(pts).z / 2.0;
    (z > 0 ? p.up_area : p.down_area) += std::abs(z);
  }
  return p;
}

}  // namespace procex::test
