#include "core/geom/symmetric_eigen.h"

#include <cmath>

#include <glm/matrix.hpp>

namespace procex {

// Cyclic Jacobi rotations: a 3x3 converges to full precision in a handful of
// sweeps, and the vectors stay orthonormal to rounding whatever the spread of
// the eigenvalues.
glm::dmat3 symmetric_eigenvectors(glm::dmat3& a) {
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

}  // namespace procex
