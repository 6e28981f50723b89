// Affine maps as glTF nodes can hold them. A glTF node matrix must decompose
// into translation * rotation * scale, which a shear does not (a leaning
// pillar, a window fitted to a skewed cell). Any affine map with an
// invertible 3x3 part M does split into two such nodes through the singular
// value decomposition M = U S V^T: an outer node T * U * S and an inner node
// V^T, a pure rotation.
#pragma once

#include <glm/mat4x4.hpp>

namespace procex {

// Whether the 3x3 part's columns are perpendicular (to within
// kTrsColumnCosine): then the matrix is translation * rotation * scale
// (a negative scale for a mirror) and needs no split.
bool is_trs(const glm::dmat4& transform);

struct TrsSplit {
  glm::dmat4 outer{1.0};  // translation * rotation * scale
  glm::dmat4 inner{1.0};  // a rotation (determinant +1)
};

// outer * inner == transform (to rounding). The transform must be affine
// with an invertible 3x3 part (check_instance in placement.h checks both).
TrsSplit split_trs(const glm::dmat4& transform);

}  // namespace procex
