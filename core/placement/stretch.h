// Stretching a mesh between control points (the paper's bones, section 3.6):
// an affine map from the mesh's bounding box onto a parallelepiped fixed by
// four points, so a pillar's bottom follows one anchor and its top another,
// or a window fills the cell a grid gives it.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/geom/anchor.h"
#include "core/placement/box.h"
#include "core/placement/repeat.h"

namespace procex {

// Where the box's corner lo and the far ends of its three edges from lo go:
// lo -> origin, lo + (size.x, 0, 0) -> x_end, and so on for y and z. On an
// axis where the box is flat (size 0), the mesh keeps its own scale and only
// the direction origin -> end counts.
struct ControlPoints {
  glm::dvec3 origin{0.0};
  glm::dvec3 x_end{1.0, 0.0, 0.0};
  glm::dvec3 y_end{0.0, 1.0, 0.0};
  glm::dvec3 z_end{0.0, 0.0, 1.0};
};

// The affine map taking the box onto the control points. Throws
// PlacementError if a control point is not finite, an end coincides with the
// origin, or the three edges are coplanar (the mesh would collapse).
glm::dmat4 map_box(const Box3& box, const ControlPoints& to);

// Stretches the box along its own axis `axis` (0 x, 1 y, 2 z) so that its lo
// side lies on `from` and its hi side on `to`: a pillar (axis y) from a
// ground anchor to an eave anchor. The other two axes keep their size and
// follow the frame (x along, y up, z normal, as in frame_transform.h); the
// box point at `pivot` fractions of those two axes sits on the line from
// `from` to `to`. When to - from is not parallel to the frame's axis the
// mesh leans (a shear), as a bone does. Throws PlacementError if the box is
// flat along `axis`, from == to, or the result collapses.
glm::dmat4 stretch_between(const Box3& box, const Frame& frame, const glm::dvec3& from, const glm::dvec3& to,
                           int axis = 1, const glm::dvec3& pivot = {0.5, 0.5, 0.0});

// Fits the box into a repetition cell (repeat.h) with a margin on every side
// in the face: x fills the cell's width, y its height (or keeps the mesh's own
// height above the cell's origin when the cell has none), z keeps the mesh's
// depth with its back (z lo) on the face. A window that fills the spacing of
// a grid. Throws PlacementError if the margins leave no room.
glm::dmat4 fit_to_cell(const Box3& box, const Cell& cell, double margin = 0.0);

}  // namespace procex
