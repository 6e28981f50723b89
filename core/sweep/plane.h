// Planes of the sweep (the paper's s-planes). A face swept by an edge is the plane n.x - k z = c, where n
// is the edge's inward unit normal in the plan and k = tan(angle from vertical):
// at height z the edge's line has moved k z inward.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/geom/cross.h"

namespace procex::engine {

struct Plane {
  glm::dvec2 n{0.0};  // inward unit normal in the plan
  double k = 0.0;     // inward offset per unit height
  double c = 0.0;     // n.x - k z = c

  // The plane of an edge through `point` (at height z0) running along unit `dir`.
  static Plane through(glm::dvec2 point, double z0, glm::dvec2 dir, double k) {
    const glm::dvec2 n{-dir.y, dir.x};
    return {n, k, n.x * point.x + n.y * point.y - k * z0};
  }
  double offset_at(double z) const { return c + k * z; }
  double signed_distance(glm::dvec2 p, double z) const { return n.x * p.x + n.y * p.y - offset_at(z); }
};

// Planes by field, side by side, as meeting_heights reads them: one corner
// tested against many planes is the sweep's inner loop.
struct PlaneColumns {
  std::vector<double> nx, ny, k, c;

  void push_back(const Plane& pl) {
    nx.push_back(pl.n.x);
    ny.push_back(pl.n.y);
    k.push_back(pl.k);
    c.push_back(pl.c);
  }
  void reserve(std::size_t n) {
    for (auto* v : {&nx, &ny, &k, &c}) v->reserve(n);
  }
  void clear() {
    for (auto* v : {&nx, &ny, &k, &c}) v->clear();
  }
};

// How the line where planes a and b cross moves over the sweep plane per unit
// of height: differentiating n.x - k z = c, v solves n_a.v = k_a, n_b.v = k_b.
// Solved along the two half-angle directions m ~ n_a + n_b and t ~ n_a - n_b,
// where the system splits into m.v = (k_a + k_b) / |n_a + n_b| and t.v =
// (k_a - k_b) / |n_a - n_b|. Cramer's rule, (k_a n_b.y - k_b n_a.y) / det,
// cancels catastrophically between nearly parallel edges of one slope (edges
// collinear only up to the rounding of rotated coordinates): det ~1e-10 leaves
// the velocity wrong by 1e-6 relative, which a kilometre of rise turns into
// millimetres. Here equal slopes give t.v = 0 exactly, whatever the angle.
// Meaningful only where cross(a.n, b.n) is away from zero.
inline glm::dvec2 crossing_velocity(const Plane& a, const Plane& b) {
  const glm::dvec2 sum = a.n + b.n, diff = a.n - b.n;
  const double ls = sum.x * sum.x + sum.y * sum.y, ld = diff.x * diff.x + diff.y * diff.y;
  return sum * ((a.k + b.k) / ls) + diff * ((a.k - b.k) / ld);
}

// How much where planes a, b and c meet moves when the planes do, per unit
// each plane's offset moves: the sum of the lengths of the columns of the
// inverse of their rows (n, -k), |b x c| + |c x a| + |a x b| over |a.(b x c)|.
// Rounding moves every line of a plan by about an ulp of its extent, and
// where the three planes are nearly parallel (an edge between two slight
// turns, as along a finely drawn circle) their meeting moves by that over the
// turns' product: a regular 262,144-gon's edge events lie 3.5e-5 m apart at a
// 100 m radius, 17 times the clustering distance. The determinant is taken
// of differences of rows, which are exact between nearly parallel planes, so
// it keeps its digits where it is the product of three small turns. HUGE_VAL
// where the planes do not meet in one point.
inline double meeting_condition(const Plane& a, const Plane& b, const Plane& c) {
  const glm::dvec3 ra{a.n, -a.k}, rb{b.n, -b.k}, rc{c.n, -c.k};
  const double det = std::abs(glm::dot(ra - rb, glm::cross(rb, rc - rb)));
  const double columns = glm::length(glm::cross(rb, rc - rb)) + glm::length(glm::cross(rc, ra - rc)) +
                         glm::length(glm::cross(ra, rb - ra));
  return det > 0.0 ? columns / det : HUGE_VAL;
}

}  // namespace procex::engine
