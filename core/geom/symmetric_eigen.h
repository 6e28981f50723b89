// Eigenvectors of a symmetric 3x3 matrix: the principal axes of a point set
// (an oriented bounding box) and the singular value decomposition of an
// affine map (a glTF node split) both rest on them.
#pragma once

#include <glm/mat3x3.hpp>

namespace procex {

// The eigenvectors of the symmetric matrix a as the columns of the result,
// orthonormal; a becomes diagonal, holding the eigenvalues in the same order.
glm::dmat3 symmetric_eigenvectors(glm::dmat3& a);

}  // namespace procex
