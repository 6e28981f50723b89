// Placing a mesh at an anchor's frame: the 4x4 matrix taking the mesh's own
// coordinates to the world.
//
// Convention: the mesh's local x runs along the frame's `along` (the edge
// direction), y along `up` (up the face), z along `normal` (out of the face).
// So a mesh modelled as seen from outside, standing on the xz plane with its
// front facing +z (a window, a dormer, a pillar standing on y = 0), lands
// on a facade the right way round and the right way up. Its local origin (or
// `pivot`) lands on the frame's origin.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/geom/anchor.h"

namespace procex {

struct FramePlacement {
  glm::dvec3 pivot{0.0};   // the mesh point (own coordinates) put on the frame's origin; see Box3::at
  glm::dvec3 scale{1.0};   // per local axis, about the pivot; a negative scale mirrors
  glm::dvec3 offset{0.0};  // then a shift in frame axes (along, up, normal), metres
};

// The frame as a matrix: columns along, up, normal, origin. Throws
// PlacementError if the axes are not unit, perpendicular and right-handed
// (cross(along, up) == normal) to within kFrameOrthonormality, or not finite.
glm::dmat4 frame_matrix(const Frame& frame);

// frame_matrix(frame) * translate(offset) * scale(scale) * translate(-pivot).
// Throws PlacementError for a bad frame or a zero or non-finite scale.
glm::dmat4 place_at(const Frame& frame, const FramePlacement& placement = {});

// A right-handed orthonormal frame at origin: along normalised, up made
// perpendicular to it (Gram-Schmidt), normal = cross(along, up). Throws
// PlacementError if along is zero or up is parallel to it.
Frame orthonormal_frame(const glm::dvec3& origin, const glm::dvec3& along, const glm::dvec3& up);

}  // namespace procex
