#include "nodes/support/edge_labels.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/geom/nesting.h"

namespace procex {
namespace {

double compass_deg(const glm::dvec2& v) {
  const double a = std::atan2(v.y, v.x) * 180.0 / M_PI;
  return a < 0 ? a + 360.0 : a;
}

}  // namespace

std::vector<EdgeLabels> label_edges(const Footprint& fp, const LabelOptions& options) {
  std::vector<std::vector<glm::dvec2>> loops;
  for (const Loop& loop : fp.loops) loops.push_back(loop.points);
  const LoopNesting nesting = loop_nesting(loops);

  std::vector<EdgeLabels> out;
  std::vector<glm::dvec2> normals;
  double longest = -1;
  glm::dvec2 street(0, -1);
  for (std::size_t li = 0; li < fp.loops.size(); ++li) {
    const auto& pts = fp.loops[li].points;
    const bool inner = nesting.depth[li] % 2 == 1;
    // Material lies to the left of an edge of a counter-clockwise outer loop
    // or a clockwise hole; flip the normal of loops that run the other way.
    const bool ccw = twice_signed_area(pts) > 0;
    const double side = (ccw != inner) ? 1.0 : -1.0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const glm::dvec2 d = pts[(k + 1) % pts.size()] - pts[k];
      EdgeLabels e;
      e.loop = li, e.edge = k, e.id = fp.loops[li].edges[k].id, e.inner = inner;
      e.party = std::find(options.party.begin(), options.party.end(), e.id) != options.party.end();
      e.length = glm::length(d);
      const glm::dvec2 n = e.length > 0 ? side * glm::dvec2(d.y, -d.x) / e.length : glm::dvec2(0);
      e.normal_deg = compass_deg(n);
      e.length_class = e.length < options.short_below ? LengthClass::Short
                       : e.length > options.long_above ? LengthClass::Long
                                                       : LengthClass::Medium;
      const bool on_street = std::find(options.street.begin(), options.street.end(), e.id) != options.street.end();
      if (!inner && !e.party && (on_street || options.street.empty()) && e.length > longest) longest = e.length, street = n;
      normals.push_back(n);
      out.push_back(e);
    }
  }
  if (options.street_deg) {
    const double a = *options.street_deg * M_PI / 180.0;
    street = {std::cos(a), std::sin(a)};
  }
  const double cos45 = std::sqrt(0.5);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double c = glm::dot(normals[i], street);
    const bool by_data = !options.street.empty();
    const bool on_street = by_data && std::find(options.street.begin(), options.street.end(), out[i].id) != options.street.end();
    out[i].orientation = on_street || (!by_data && c >= cos45) ? Orientation::Street
                         : c <= -cos45                        ? Orientation::Back
                                                              : Orientation::Side;
  }
  return out;
}

}  // namespace procex
