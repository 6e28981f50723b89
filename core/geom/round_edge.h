// Faces of a solid's surface that meet along one edge, paired round it.
// Where parts of a solid touch along a line (two blocks sharing only an
// edge: a ledge as deep as its wing beside a soffit), the edge has several
// faces each way. Going round the edge, the solid lies after each face that
// runs against the edge's axis and before each that runs along it, so the two
// kinds alternate, and each face's twin, the face across the part of the
// solid it bounds, is its neighbour on that side. Faces that do not alternate
// overlap or fold over each other: no solid has that surface.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace procex {

struct FaceAtEdge {
  glm::dvec3 normal;  // outward, unit length
  bool along;         // its boundary runs along the edge's axis (else against it)
};

// For each face, the index of its twin; nullopt where the faces do not
// alternate round the edge or two of them leave it the same way.
std::optional<std::vector<std::size_t>> twins_round_edge(const glm::dvec3& axis, std::span<const FaceAtEdge> faces);

}  // namespace procex
