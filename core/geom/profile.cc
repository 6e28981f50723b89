#include "core/geom/profile.h"

#include <cmath>

#include "core/geom/error.h"

namespace procex {

Profile Profile::straight(double angle_deg, double height, std::string tag) {
  const double inward = height * std::tan(angle_deg * M_PI / 180.0);
  return {"straight", {{0.0, 0.0}, {-inward, height}}, {std::move(tag)}};
}

double Profile::angle_deg(std::size_t segment) const {
  const glm::dvec2 d = points[segment + 1] - points[segment];
  // Outward offset growing with height leans out: a negative angle.
  return std::atan2(-d.x, d.y) * 180.0 / M_PI;
}

void check_profile(const Profile& p) {
  const std::string where = "profile '" + p.name + "'";
  if (p.points.size() < 2) throw InputError(where + " needs at least two points (one segment)");
  if (p.points[0] != glm::dvec2(0.0)) throw InputError(where + " must start at offset 0, height 0");
  if (!p.tags.empty() && p.tags.size() != p.segments())
    throw InputError(where + " has " + std::to_string(p.tags.size()) + " tags for " +
                     std::to_string(p.segments()) + " segments");
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    if (!std::isfinite(p.points[i].x) || !std::isfinite(p.points[i].y))
      throw InputError(where + ": point " + std::to_string(i) + " is not a finite number");
    if (i > 0 && p.points[i].y < p.points[i - 1].y)
      throw InputError(where + ": segment " + std::to_string(i - 1) + " goes down (height " +
                       std::to_string(p.points[i - 1].y) + " to " + std::to_string(p.points[i].y) +
                       "); profiles only rise");
    if (i > 0 && p.points[i] == p.points[i - 1])
      throw InputError(where + ": segment " + std::to_string(i - 1) + " has zero length");
  }
}

}  // namespace procex
