#include "core/geom/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace procex {

namespace {

// Ulps of the largest coordinate below which points cannot be told apart.
constexpr double kCoordinateUlps = 16.0;

}  // namespace

double length_scale(const Footprint& footprint) {
  double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x;
  double hi_x = -lo_x, hi_y = -lo_x;
  for (const Loop& loop : footprint.loops) {
    for (const glm::dvec2& p : loop.points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      lo_x = std::min(lo_x, p.x);
      lo_y = std::min(lo_y, p.y);
      hi_x = std::max(hi_x, p.x);
      hi_y = std::max(hi_y, p.y);
    }
  }
  if (hi_x < lo_x) return 0.0;
  return std::hypot(hi_x - lo_x, hi_y - lo_y);
}

double rounding_distance(const Footprint& footprint) {
  double magnitude = 0.0;
  for (const Loop& loop : footprint.loops)
    for (const glm::dvec2& p : loop.points)
      if (std::isfinite(p.x) && std::isfinite(p.y)) magnitude = std::max({magnitude, std::abs(p.x), std::abs(p.y)});
  return kCoordinateUlps * std::numeric_limits<double>::epsilon() * magnitude;
}

double merge_distance(const Footprint& footprint) {
  return std::max(kVertexMergeRelative * length_scale(footprint), rounding_distance(footprint));
}

}  // namespace procex
