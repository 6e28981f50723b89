// A profile: the cross-section an edge follows as the sweep plane rises
// (paper 3.2). A polyline in the (outward offset, height) plane, starting at
// (0, 0) and never going down; each segment carries a tag that travels to the
// faces it makes ("wall", "roof", "eave", "soffit", or any user string).
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace procex {

struct Profile {
  std::string name;
  // x: outward offset from the footprint edge, y: height. points[0] is (0, 0).
  std::vector<glm::dvec2> points;
  std::vector<std::string> tags;  // one per segment (points.size() - 1); may be empty strings

  // A one-segment profile rising at angle_deg from the vertical (positive leans inward)
  // to `height`.
  static Profile straight(double angle_deg, double height, std::string tag = "roof");
  std::size_t segments() const { return points.size() < 2 ? 0 : points.size() - 1; }
  // Degrees from the vertical of segment i; +-90 for a horizontal segment.
  double angle_deg(std::size_t segment) const;
};

// Throws InputError naming the profile and segment if the profile is empty,
// does not start at (0, 0), has NaN/inf, goes down, or has a tag count that
// does not match its segments.
void check_profile(const Profile& profile);

}  // namespace procex
