// Axis-aligned bounds of a mesh in its own coordinates: what placement maps
// onto frames, cells and control points.
#pragma once

#include <glm/vec3.hpp>

#include "core/mesh/mesh.h"

namespace procex {

struct Box3 {
  glm::dvec3 lo{0.0}, hi{0.0};

  glm::dvec3 size() const { return hi - lo; }
  // The point at these fractions of the box per axis: (0,0,0) is lo, (1,1,1)
  // is hi, (0.5, 0, 0.5) the middle of the bottom.
  glm::dvec3 at(const glm::dvec3& fraction) const { return lo + fraction * (hi - lo); }
};

// Throws PlacementError if the mesh has no vertices.
Box3 bounds(const Mesh& mesh);

}  // namespace procex
