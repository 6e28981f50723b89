// A failed ValidationReport as one line for test output: which properties
// fail and the first few problems.
#pragma once

#include <algorithm>
#include <string>

#include "core/mesh/validate.h"

namespace procex {

inline std::string describe(const ValidationReport& v) {
  std::string d = "does not validate:";
  if (!v.closed) d += " not closed;";
  if (!v.manifold) d += " not manifold;";
  if (!v.oriented) d += " not oriented (volume " + std::to_string(v.volume) + ");";
  if (!v.planar) d += " not planar (max error " + std::to_string(v.max_planarity_error) + ");";
  if (!v.self_intersection_free) d += " self-intersecting;";
  for (std::size_t i = 0; i < std::min<std::size_t>(3, v.problems.size()); ++i) d += " [" + v.problems[i] + "]";
  return d;
}

}  // namespace procex
