// Which way is up in a written file. procex computes in metres with x east,
// y north and z up; glTF 2.0 says +Y is up, and Blender, Maya and Houdini
// import OBJ and PLY as +Y up too, while GIS tools expect z up.
//
// The Y-up frame is procex's turned a quarter about x: (x, y, z) becomes
// (x, z, -y). That is a rotation, not a mirror, so a plan seen from above
// keeps its handedness (east to the right of north), and the map is exact in
// floating point (a swap and a sign), so it reads back to the same numbers.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace procex {

enum class UpAxis { Y, Z };

inline glm::dvec3 to_file_axes(const glm::dvec3& p, UpAxis up) {
  return up == UpAxis::Y ? glm::dvec3(p.x, p.z, -p.y) : p;
}

inline glm::dvec3 from_file_axes(const glm::dvec3& p, UpAxis up) {
  return up == UpAxis::Y ? glm::dvec3(p.x, -p.z, p.y) : p;
}

// The rotation to_file_axes applies, as a matrix.
inline glm::dmat4 file_axes_matrix(UpAxis up) {
  glm::dmat4 r(1.0);
  if (up == UpAxis::Y) r[1] = {0, 0, -1, 0}, r[2] = {0, 1, 0, 0};  // columns: y -> -z, z -> y
  return r;
}

// A transform between procex coordinates (t: from a mesh's own frame to the
// world) seen in the file's frame at both ends: R t R^-1.
inline glm::dmat4 to_file_axes(const glm::dmat4& t, UpAxis up) {
  if (up == UpAxis::Z) return t;
  const glm::dmat4 r = file_axes_matrix(up);
  return r * t * glm::transpose(r);  // R is a rotation: its inverse is its transpose
}

}  // namespace procex
