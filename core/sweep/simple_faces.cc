#include "core/sweep/simple_faces.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/geom/error.h"
#include "core/geom/polygon3.h"
#include "core/geom/segment_intersections.h"

namespace procex::engine {

void check_simple_faces(const Surface& surface) {
  std::vector<glm::dvec3> points;
  std::vector<glm::dvec2> flat;
  for (std::size_t f = 0; f < surface.faces.size(); ++f) {
    const SurfaceFace& face = surface.faces[f];
    // A triangle cannot cross itself, and the base is the plan, checked
    // simple before the sweep (prepare_footprint).
    if (face.loops.size() != 1 || face.loops[0].size() < 4 || face.kind == FaceKind::Base) continue;
    points.clear();
    for (std::uint32_t v : face.loops[0]) points.push_back(surface.vertices[v]);
    // Seen as the mesh validator sees it (core/mesh/validate.cc).
    drop_axis(points, newell_normal(points), flat);
    const auto crossing = loop_crossing(flat);
    if (!crossing) continue;
    const double z = std::max(points[crossing->first].z, points[crossing->second].z);
    throw SweepError("sweep: face " + std::to_string(f) + " (of edge " + std::to_string(face.source_edge) +
                         ") folds over itself: its edges " + std::to_string(crossing->first) + " and " +
                         std::to_string(crossing->second) + " cross near height " + std::to_string(z) +
                         ", events there too close together for the sweep to order",
                     z, {face.source_edge});
  }
}

}  // namespace procex::engine
