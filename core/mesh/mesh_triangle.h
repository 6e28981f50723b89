// A mesh face's triangle, as the validator splits faces: what its checks of
// triangles (height_field.h, the pair search of validate.cc) read.
#pragma once

#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

namespace procex {

struct MeshTriangle {
  std::array<glm::dvec3, 3> p;
  std::array<std::uint32_t, 3> v;  // welded vertex ids: equal positions, equal ids
  int face;
};

}  // namespace procex
