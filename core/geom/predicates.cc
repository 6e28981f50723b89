#include "core/geom/predicates.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace procex {

namespace {

// Shewchuk's ccwerrboundA: a relative bound on the rounding error of the
// floating-point orientation determinant.
constexpr double kOrientErrorBound = 3.3306690738754716e-16;

struct Expansion {
  std::array<double, 13> terms{};
  int size = 0;

  // Adds b exactly (Shewchuk's Grow-Expansion with Two-Sum).
  void add(double b) {
    double q = b;
    for (int i = 0; i < size; ++i) {
      const double s = q + terms[i];
      const double bv = s - q;
      const double err = (q - (s - bv)) + (terms[i] - bv);
      terms[i] = err;
      q = s;
    }
    terms[size++] = q;
  }

  // Adds the exact product x * y as two terms.
  void add_product(double x, double y) {
    const double p = x * y;
    add(std::fma(x, y, -p));
    add(p);
  }

  int sign() const {
    for (int i = size - 1; i >= 0; --i)
      if (terms[i] != 0.0) return terms[i] > 0.0 ? 1 : -1;
    return 0;
  }
};

bool on_segment_collinear(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

}  // namespace

int orient2d(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const double left = (b.x - a.x) * (c.y - a.y);
  const double right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right;
  const double bound = kOrientErrorBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  // ax*by - ax*cy - ay*bx + ay*cx + bx*cy - by*cx, every product exact.
  Expansion e;
  e.add_product(a.x, b.y);
  e.add_product(-a.x, c.y);
  e.add_product(-a.y, b.x);
  e.add_product(a.y, c.x);
  e.add_product(b.x, c.y);
  e.add_product(-b.y, c.x);
  return e.sign();
}

bool segments_intersect(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const int o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment_collinear(a, b, c)) || (o2 == 0 && on_segment_collinear(a, b, d)) ||
         (o3 == 0 && on_segment_collinear(c, d, a)) || (o4 == 0 && on_segment_collinear(c, d, b));
}

}  // namespace procex
