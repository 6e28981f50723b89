// Plan transforms the generated inputs go through (issue 12: rotated by 90,
// 45, 30 degrees and at random, mirrored, scaled by 1e-3..1e4, moved to
// (5e5, 5e6) and (1e9, -1e9)), and the roof checks compare against.
#pragma once

#include <random>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace procex::testing {

// x -> linear * x + offset; heights scale by sqrt|det linear|.
struct PlanTransform {
  std::string name = "identity";
  double linear[2][2] = {{1, 0}, {0, 1}};
  glm::dvec2 offset{0.0};

  glm::dvec2 apply(glm::dvec2 p) const;
  double height_scale() const;
  bool mirrors() const;

  static PlanTransform rotation(double degrees);
  static PlanTransform mirror();  // x -> -x
  static PlanTransform scale(double factor);
  static PlanTransform translation(glm::dvec2 by);
  // this after `first`.
  PlanTransform after(const PlanTransform& first) const;
};

// The kind-th of the generators' transforms (kind modulo their number):
// identity, rotations by 90, 45, 30 degrees and a random angle, a mirror, a
// random scale, the two far-away translations, and a random composition.
PlanTransform generated_transform(std::size_t kind, std::mt19937_64& rng);

using Plan = std::vector<std::vector<glm::dvec2>>;
Plan apply(const PlanTransform& t, const Plan& plan);

}  // namespace procex::testing
