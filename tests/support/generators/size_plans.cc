#include "tests/support/generators/size_plans.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace procex::testing {
namespace {

NamedPlan polar(std::string name, const std::vector<double>& angles, const std::vector<double>& radii) {
  std::vector<glm::dvec2> loop;
  for (std::size_t i = 0; i < angles.size(); ++i)
    loop.emplace_back(radii[i] * std::cos(angles[i]), radii[i] * std::sin(angles[i]));
  return {std::move(name), {std::move(loop)}};
}

std::vector<double> even_angles(std::size_t n) {
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(n);
  return a;
}

}  // namespace

NamedPlan regular_polygon(std::size_t n, double radius) {
  return polar("regular " + std::to_string(n) + "-gon of radius " + std::to_string(radius), even_angles(n),
               std::vector<double>(n, radius));
}

NamedPlan star(std::size_t n, double outer, double inner) {
  std::vector<double> radii(n);
  for (std::size_t i = 0; i < n; ++i) radii[i] = i % 2 == 0 ? outer : inner;
  return polar("star of " + std::to_string(n) + " vertices, radii " + std::to_string(outer) + "/" + std::to_string(inner),
               even_angles(n), radii);
}

NamedPlan jittered_star(std::size_t n, double outer, double inner, double jitter, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> moved(-jitter, jitter);
  std::vector<double> radii(n);
  for (std::size_t i = 0; i < n; ++i) radii[i] = (i % 2 == 0 ? outer : inner) + moved(rng);
  return polar("star of " + std::to_string(n) + " vertices, radii " + std::to_string(outer) + "/" +
                   std::to_string(inner) + " each moved by up to " + std::to_string(jitter),
               even_angles(n), radii);
}

NamedPlan random_star_shaped(std::size_t n, double radius, std::mt19937_64& rng) {
  // Angles jittered within their own slot keep order and a positive gap.
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> angles = even_angles(n), radii(n);
  for (std::size_t i = 0; i < n; ++i) {
    angles[i] += (0.1 + 0.8 * unit(rng)) * 2.0 * M_PI / static_cast<double>(n);
    radii[i] = radius * (0.3 + 0.7 * unit(rng));
  }
  return polar("random star-shaped polygon of " + std::to_string(n) + " vertices", angles, radii);
}

}  // namespace procex::testing
