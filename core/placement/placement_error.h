// Errors raised by core/placement on unusable placement input: a degenerate
// frame, a span or control points that collapse a mesh, a repetition that
// cannot be laid out. Each message names the offending value.
#pragma once

#include <stdexcept>
#include <string>

#include <glm/vec3.hpp>

namespace procex {

class PlacementError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "(x, y, z)" with shortest round-trip numbers, for messages.
std::string vector_text(const glm::dvec3& v);

}  // namespace procex
