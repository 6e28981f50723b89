#include "core/placement/trs_split.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/geom/symmetric_eigen.h"
#include "core/geom/tolerances.h"

namespace procex {

bool is_trs(const glm::dmat4& transform) {
  const glm::dvec3 c[3] = {glm::dvec3(transform[0]), glm::dvec3(transform[1]), glm::dvec3(transform[2])};
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(glm::dot(c[i], c[j])) > kTrsColumnCosine * glm::length(c[i]) * glm::length(c[j])) return false;
  return true;
}

TrsSplit split_trs(const glm::dmat4& transform) {
  const glm::dmat3 m(transform);
  glm::dmat3 ata = glm::transpose(m) * m;
  glm::dmat3 v = symmetric_eigenvectors(ata);
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
