#include "nodes/support/shapes.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace procex {
namespace {

using Loop2 = std::vector<glm::dvec2>;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// Points given in [0, w] x [0, d], moved so the bounding box is centred.
Loop2 centred(Loop2 loop, double w, double d) {
  for (glm::dvec2& p : loop) p -= glm::dvec2(w / 2, d / 2);
  return loop;
}

}  // namespace

std::vector<std::vector<glm::dvec2>> make_shape(std::string_view shape, const ShapeSize& s) {
  const double w = s.width, d = s.depth, t = s.arm;
  require(w > 0 && d > 0, "width and depth must be positive");
  if (shape == "rectangle") return {centred({{0, 0}, {w, 0}, {w, d}, {0, d}}, w, d)};
  if (shape == "ngon") {
    require(s.sides >= 3, "sides must be at least 3 (got " + std::to_string(s.sides) + ")");
    Loop2 loop;
    for (int i = 0; i < s.sides; ++i) {
      const double a = 2 * M_PI * i / s.sides;
      loop.push_back({w / 2 * std::cos(a), w / 2 * std::sin(a)});
    }
    return {loop};
  }
  require(t > 0, "arm must be positive");
  if (shape == "l") {
    require(t < w && t < d, "arm must be narrower than width and depth");
    return {centred({{0, 0}, {w, 0}, {w, t}, {t, t}, {t, d}, {0, d}}, w, d)};
  }
  if (shape == "t") {
    require(t < w && t < d, "arm must be narrower than width and depth");
    const double x0 = (w - t) / 2, x1 = (w + t) / 2;
    return {centred({{x0, 0}, {x1, 0}, {x1, d - t}, {w, d - t}, {w, d}, {0, d}, {0, d - t}, {x0, d - t}}, w, d)};
  }
  if (shape == "u") {
    require(2 * t < w && t < d, "arm must be under half the width and under the depth");
    return {centred({{0, 0}, {w, 0}, {w, d}, {w - t, d}, {w - t, t}, {t, t}, {t, d}, {0, d}}, w, d)};
  }
  if (shape == "courtyard") {
    require(2 * t < w && 2 * t < d, "arm (the ring's thickness) must be under half the width and the depth");
    return {centred({{0, 0}, {w, 0}, {w, d}, {0, d}}, w, d),
            centred({{t, t}, {t, d - t}, {w - t, d - t}, {w - t, t}}, w, d)};
  }
  throw std::invalid_argument("unknown shape '" + std::string(shape) + "'");
}

}  // namespace procex
