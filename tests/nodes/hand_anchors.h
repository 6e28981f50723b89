// Anchors resolved by hand, as the sweep will resolve them on walls that rise
// straight up: one per edge of a footprint's outer loop, at height z and a
// fraction along the edge, framed on the wall (along the edge, up, outward),
// spanning the wall's width. Until Extrude fills TaggedMesh::anchors itself,
// the node tests put these on Extrude's output.
#pragma once

#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/geom/anchor.h"
#include "core/geom/footprint.h"

namespace procex::test {

// Edges in `absent` resolve to absent ("edge gone").
inline std::vector<ResolvedAnchor> wall_anchors(const Footprint& fp, const std::string& name, double z,
                                                double fraction, const std::vector<int>& absent = {}) {
  std::vector<ResolvedAnchor> out;
  const Loop& loop = fp.loops.at(0);
  for (std::size_t e = 0; e < loop.points.size(); ++e) {
    ResolvedAnchor& a = out.emplace_back();
    a.name = name;
    a.edge_id = loop.edges[e].id;
    a.present = std::find(absent.begin(), absent.end(), static_cast<int>(e)) == absent.end();
    if (!a.present) {
      a.reason = "edge gone";
      continue;
    }
    const glm::dvec2 p = loop.points[e], q = loop.points[(e + 1) % loop.points.size()];
    const glm::dvec3 from(p, z), to(q, z);
    a.frame = {from + fraction * (to - from), glm::normalize(to - from), {0, 0, 1}, {}};
    a.frame.normal = glm::cross(a.frame.along, a.frame.up);
    a.span_from = from, a.span_to = to;
  }
  return out;
}

}  // namespace procex::test
