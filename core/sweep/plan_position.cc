#include "core/sweep/plan_position.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace procex::engine {
namespace {

std::string text(const PlanPosition& at, const double* values, int n) {
  std::ostringstream out;
  // Decimals down to the resolution: 5000000.1234567 at 1e-7, where the
  // default six significant digits said 5e+06 for every point of a building.
  if (at.resolution > 0.0) {
    out.setf(std::ios::fixed);
    out.precision(std::clamp(static_cast<int>(std::ceil(-std::log10(at.resolution))), 0, 12));
  }
  out << '(';
  for (int i = 0; i < n; ++i) out << (i ? ", " : "") << values[i];
  out << ')';
  return out.str();
}

}  // namespace

std::string PlanPosition::operator()(glm::dvec2 local) const {
  const glm::dvec2 p = local + centre;
  const double values[] = {p.x, p.y};
  return text(*this, values, 2);
}

std::string PlanPosition::operator()(glm::dvec3 local) const {
  const double values[] = {local.x + centre.x, local.y + centre.y, local.z};
  return text(*this, values, 3);
}

}  // namespace procex::engine
