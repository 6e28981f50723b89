#include "core/placement/trs_split.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/geom/tolerances.h"

namespace procex {

bool is_trs(const glm::dmat4& transform) {
  const glm::dvec3 c[3] = {glm::dvec3(transform[0]), glm::dvec3(transform[1]), glm::dvec3(transform[2])};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(glm::dot(c[i], c[j])) > kTrsColumnCosine * glm::length(c[i]) * glm::length(c[j])) return false;
  return true;
}

namespace {

// Eigenvectors of the symmetric matrix a (as the columns of the result, a
// becoming diagonal), by cyclic Jacobi rotations: a 3x3 converges to full
// precision in a handful of sweeps.
glm::dmat3 jacobi_eigenvectors(glm::dmat3& a) {
  glm::dmat3 v(1.0);
  for (int sweep = 0; sweep < 32; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-32 * diag) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1));
        const double c = 1 / std::sqrt(t * t + 1), s = t * c;
        glm::dmat3 r(1.0);  // a <- r^T a r zeroes a[p][q]
        r[p][p] = c;
        r[q][q] = c;
        r[q][p] = s;
        r[p][q] = -s;
        a = glm::transpose(r) * a * r;
        v = v * r;
      }
  }
  return v;
}

}  // namespace

TrsSplit split_trs(const glm::dmat4& transform) {
  const glm::dmat3 m(transform);
  glm::dmat3 ata = glm::transpose(m) * m;
  glm::dmat3 v = jacobi_eigenvectors(ata);
  if (glm::determinant(v) < 0) v[2] = -v[2];  // the inner node must be a rotation
  // U's columns: M v_i / sigma_i, made exactly orthonormal and right-handed;
  // a mirror shows as a negative third scale.
  glm::dvec3 scale, u[3];
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 mv = m * v[i];
    scale[i] = glm::length(mv);
    u[i] = mv / scale[i];
  }
  u[1] = glm::normalize(u[1] - glm::dot(u[1], u[0]) * u[0]);
  const glm::dvec3 third = glm::cross(u[0], u[1]);
  if (glm::dot(third, u[2]) < 0) scale[2] = -scale[2];
  u[2] = third;
  TrsSplit out;
  for (int i = 0; i < 3; ++i) out.outer[i] = glm::dvec4(u[i] * scale[i], 0.0);
  out.outer[3] = transform[3];
  out.inner = glm::dmat4(glm::transpose(v));
  return out;
}

}  // namespace procex
