#include "core/placement/box.h"

#include <glm/common.hpp>

#include "core/placement/placement_error.h"

namespace procex {

Box3 bounds(const Mesh& mesh) {
  if (mesh.n_vertices() == 0) throw PlacementError("the mesh to place has no vertices, so it has no bounds");
  Box3 box;
  bool first = true;
  for (const auto v : mesh.vertices()) {
    const Mesh::Point& p = mesh.point(v);
    const glm::dvec3 q{p[0], p[1], p[2]};
    box.lo = first ? q : glm::min(box.lo, q);
    box.hi = first ? q : glm::max(box.hi, q);
    first = false;
  }
  return box;
}

}  // namespace procex
