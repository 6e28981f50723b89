#include "nodes/support/mesh_summary.h"

#include <algorithm>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

namespace procex {

MeshSummary summarize(const MeshSet& set) {
  MeshSummary s;
  s.meshes = set.parts.size();
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  std::vector<glm::dvec3> pts;
  for (const TaggedMesh& part : set.parts) {
    for (const Instance& in : part.placed.instances) ++s.placed[part.placed.meshes[in.mesh].name];
    const Mesh& m = *part.mesh;
    for (const auto v : m.vertices()) {
      const glm::dvec3 p(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    for (const auto f : m.faces()) {
      ++s.faces;
      ++s.faces_per_tag[face_tag(part, static_cast<std::size_t>(f.idx()))];
      // Divergence theorem over a fan: exact for planar polygons, convex or not.
      pts.clear();
      for (const auto v : m.fv_range(f)) pts.push_back({m.point(v)[0], m.point(v)[1], m.point(v)[2]});
      for (std::size_t k = 1; k + 1 < pts.size(); ++k) s.volume += glm::dot(pts[0], glm::cross(pts[k], pts[k + 1])) / 6.0;
    }
  }
  if (lo.x <= hi.x) s.min = lo, s.max = hi;
  return s;
}

}  // namespace procex
