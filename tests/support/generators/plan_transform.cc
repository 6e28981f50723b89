#include "tests/support/generators/plan_transform.h"

#include <cmath>

namespace procex::testing {

glm::dvec2 PlanTransform::apply(glm::dvec2 p) const {
  return {linear[0][0] * p.x + linear[0][1] * p.y + offset.x, linear[1][0] * p.x + linear[1][1] * p.y + offset.y};
}

double PlanTransform::height_scale() const {
  return std::sqrt(std::abs(linear[0][0] * linear[1][1] - linear[0][1] * linear[1][0]));
}

bool PlanTransform::mirrors() const { return linear[0][0] * linear[1][1] - linear[0][1] * linear[1][0] < 0.0; }

PlanTransform PlanTransform::rotation(double degrees) {
  PlanTransform t;
  t.name = "rotated by " + std::to_string(degrees) + " degrees";
  // Quarter turns exactly: cos(pi / 2) is not 0 in doubles.
  const double quarter = degrees / 90.0;
  double c = std::cos(degrees * M_PI / 180.0), s = std::sin(degrees * M_PI / 180.0);
  if (quarter == std::round(quarter)) {
    const int q = ((static_cast<int>(quarter) % 4) + 4) % 4;
    c = q == 0 ? 1 : q == 2 ? -1 : 0;
    s = q == 1 ? 1 : q == 3 ? -1 : 0;
  }
  t.linear[0][0] = c;
  t.linear[0][1] = -s;
  t.linear[1][0] = s;
  t.linear[1][1] = c;
  return t;
}

PlanTransform PlanTransform::mirror() {
  PlanTransform t;
  t.name = "mirrored";
  t.linear[0][0] = -1;
  return t;
}

PlanTransform PlanTransform::scale(double factor) {
  PlanTransform t;
  t.name = "scaled by " + std::to_string(factor);
  t.linear[0][0] = t.linear[1][1] = factor;
  return t;
}

PlanTransform PlanTransform::translation(glm::dvec2 by) {
  PlanTransform t;
  t.name = "moved to (" + std::to_string(by.x) + ", " + std::to_string(by.y) + ")";
  t.offset = by;
  return t;
}

PlanTransform PlanTransform::after(const PlanTransform& first) const {
  PlanTransform t;
  t.name = first.name + ", " + name;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) t.linear[i][j] = linear[i][0] * first.linear[0][j] + linear[i][1] * first.linear[1][j];
  t.offset = apply(first.offset);
  return t;
}

PlanTransform generated_transform(std::size_t kind, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto random_scale = [&] { return std::pow(10.0, -3.0 + 7.0 * unit(rng)); };
  switch (kind % 10) {
    case 0: return {};
    case 1: return PlanTransform::rotation(90);
    case 2: return PlanTransform::rotation(45);
    case 3: return PlanTransform::rotation(30);
    case 4: return PlanTransform::rotation(360.0 * unit(rng));
    case 5: return PlanTransform::mirror();
    case 6: return PlanTransform::scale(random_scale());
    case 7: return PlanTransform::translation({5e5, 5e6});
    case 8: return PlanTransform::translation({1e9, -1e9});
    default: {
      // Small buildings stay near (5e5, 5e6): at 1e9 a double's step is 1.2e-7,
      // too coarse for a footprint a few millimetres across.
      PlanTransform t = PlanTransform::rotation(360.0 * unit(rng));
      if (unit(rng) < 0.5) t = t.after(PlanTransform::mirror());
      const double s = random_scale();
      t = PlanTransform::scale(s).after(t);
      return PlanTransform::translation(s >= 1.0 && unit(rng) < 0.5 ? glm::dvec2(1e9, -1e9) : glm::dvec2(5e5, 5e6))
          .after(t);
    }
  }
}

Plan apply(const PlanTransform& t, const Plan& plan) {
  Plan out = plan;
  for (auto& loop : out)
    for (glm::dvec2& p : loop) p = t.apply(p);
  return out;
}

}  // namespace procex::testing
