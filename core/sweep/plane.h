// Planes of the sweep (the paper's s-planes) and the small linear algebra that
// intersects them. A face swept by an edge is the plane n.x - k z = c, where n
// is the edge's inward unit normal in the plan and k = tan(angle from vertical):
// at height z the edge's line has moved k z inward.
#pragma once

#include <cmath>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

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
  // A vertical plane through `point` with normal `normal` (a guide for corners
  // between parallel coplanar edges).
  static Plane vertical(glm::dvec2 point, glm::dvec2 normal) {
    return {normal, 0.0, normal.x * point.x + normal.y * point.y};
  }
  double offset_at(double z) const { return c + k * z; }
  double signed_distance(glm::dvec2 p, double z) const { return n.x * p.x + n.y * p.y - offset_at(z); }
};

inline double cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

// Where the lines of two planes meet on the sweep plane at height z; empty if
// the lines are parallel (|sin| below min_sin).
inline std::optional<glm::dvec2> meet2(const Plane& a, const Plane& b, double z, double min_sin) {
  const double det = cross(a.n, b.n);
  if (std::abs(det) < min_sin) return std::nullopt;
  const double ra = a.offset_at(z), rb = b.offset_at(z);
  return glm::dvec2{(ra * b.n.y - rb * a.n.y) / det, (a.n.x * rb - b.n.x * ra) / det};
}

// The point where three planes meet; empty if they do not meet in one point.
inline std::optional<glm::dvec3> meet3(const Plane& a, const Plane& b, const Plane& c, double min_det) {
  // Rows (n.x, n.y, -k), right-hand side c; Cramer's rule.
  const glm::dvec3 r0{a.n.x, a.n.y, -a.k}, r1{b.n.x, b.n.y, -b.k}, r2{c.n.x, c.n.y, -c.k};
  const glm::dvec3 c12{r1.y * r2.z - r1.z * r2.y, r1.z * r2.x - r1.x * r2.z, r1.x * r2.y - r1.y * r2.x};
  const double det = r0.x * c12.x + r0.y * c12.y + r0.z * c12.z;
  const double scale = 1.0 + std::abs(a.k) + std::abs(b.k) + std::abs(c.k);
  if (std::abs(det) < min_det * scale) return std::nullopt;
  const glm::dvec3 c20{r2.y * r0.z - r2.z * r0.y, r2.z * r0.x - r2.x * r0.z, r2.x * r0.y - r2.y * r0.x};
  const glm::dvec3 c01{r0.y * r1.z - r0.z * r1.y, r0.z * r1.x - r0.x * r1.z, r0.x * r1.y - r0.y * r1.x};
  const glm::dvec3 p = (a.c * c12 + b.c * c20 + c.c * c01) / det;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return std::nullopt;
  return p;
}

}  // namespace procex::engine
