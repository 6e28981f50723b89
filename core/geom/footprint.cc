#include "core/geom/footprint.h"

namespace procex {

Footprint make_footprint(const std::vector<std::vector<glm::dvec2>>& loops, double angle_deg) {
  Footprint fp;
  std::int32_t next_id = 0;
  for (const auto& pts : loops) {
    Loop loop;
    loop.points = pts;
    loop.edges.reserve(pts.size());
    for (std::size_t k = 0; k < pts.size(); ++k) loop.edges.push_back({angle_deg, next_id++});
    fp.loops.push_back(std::move(loop));
  }
  return fp;
}

}  // namespace procex
