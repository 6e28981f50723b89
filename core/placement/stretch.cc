#include "core/placement/stretch.h"

#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "core/placement/frame_transform.h"
#include "core/placement/placement_error.h"
#include "core/geom/tolerances.h"

namespace procex {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

const char* const kAxisNames[3] = {"x", "y", "z"};

// Where the end of the box's edge along `axis` goes so that the mesh keeps
// its own size on that axis: `direction` (unit) scaled by the box's extent,
// or the unit direction itself where the box is flat.
glm::dvec3 keep_size(const Box3& box, int axis, const glm::dvec3& origin, const glm::dvec3& direction) {
  const double size = box.size()[axis];
  return origin + (size > 0.0 ? size : 1.0) * direction;
}

}  // namespace

glm::dmat4 map_box(const Box3& box, const ControlPoints& to) {
  const glm::dvec3 ends[3] = {to.x_end, to.y_end, to.z_end};
  if (!finite(to.origin) || !finite(ends[0]) || !finite(ends[1]) || !finite(ends[2]) || !finite(box.lo) ||
      !finite(box.hi))
    throw PlacementError("control points and bounds must be finite: origin " + vector_text(to.origin) + ", x end " +
                         vector_text(ends[0]) + ", y end " + vector_text(ends[1]) + ", z end " + vector_text(ends[2]));
  const glm::dvec3 size = box.size();
  glm::dmat4 m(1.0);
  double largest = 0.0;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 edge = ends[k] - to.origin;
    const double length = glm::length(edge);
    if (!(length > 0.0))
      throw PlacementError(std::string("the control point for the box's ") + kAxisNames[k] + " end " +
                           vector_text(ends[k]) + " coincides with its origin " + vector_text(to.origin));
    m[k] = glm::dvec4(size[k] > 0.0 ? edge / size[k] : edge / length, 0.0);
    largest = std::max(largest, glm::length(glm::dvec3(m[k])));
  }
  if (!(std::abs(glm::determinant(glm::dmat3(m))) > kSingularDeterminantRelative * largest * largest * largest))
    throw PlacementError("the control points origin " + vector_text(to.origin) + ", x end " + vector_text(ends[0]) +
                         ", y end " + vector_text(ends[1]) + ", z end " + vector_text(ends[2]) +
                         " lie in one plane: the mesh would collapse");
  m[3] = glm::dvec4(to.origin - glm::dvec3(m * glm::dvec4(box.lo, 0.0)), 1.0);
  return m;
}

glm::dmat4 stretch_between(const Box3& box, const Frame& frame, const glm::dvec3& from, const glm::dvec3& to, int axis,
                           const glm::dvec3& pivot) {
  if (axis < 0 || axis > 2) throw PlacementError("a stretch axis is 0 (x), 1 (y) or 2 (z), not " + std::to_string(axis));
  frame_matrix(frame);  // checks the frame
  if (!(box.size()[axis] > 0.0))
    throw PlacementError(std::string("cannot stretch the mesh along ") + kAxisNames[axis] +
                         ": it is flat on that axis (its bounds " + vector_text(box.lo) + " to " + vector_text(box.hi) +
                         ")");
  if (!finite(from) || !finite(to) || from == to)
    throw PlacementError("a stretch needs two distinct finite points, not " + vector_text(from) + " and " +
                         vector_text(to));
  const glm::dvec3 axes[3] = {frame.along, frame.up, frame.normal};
  // The box's lo corner sits off the line from -> to by the pivot's share of
  // the two kept axes.
  glm::dvec3 origin = from;
  for (int k = 0; k < 3; ++k)
    if (k != axis) origin -= pivot[k] * box.size()[k] * axes[k];
  ControlPoints cp;
  glm::dvec3* ends[3] = {&cp.x_end, &cp.y_end, &cp.z_end};
  cp.origin = origin;
  for (int k = 0; k < 3; ++k) *ends[k] = k == axis ? origin + (to - from) : keep_size(box, k, origin, axes[k]);
  return map_box(box, cp);
}

glm::dmat4 fit_to_cell(const Box3& box, const Cell& cell, double margin) {
  frame_matrix(cell.frame);
  const double width = cell.width - 2 * margin;
  const bool has_height = cell.height > 0.0;
  const double height = cell.height - 2 * margin;
  if (!std::isfinite(margin) || margin < 0.0 || !(width > 0.0) || (has_height && !(height > 0.0)))
    throw PlacementError("a margin of " + std::to_string(margin) + " m leaves no room in a cell of " +
                         std::to_string(cell.width) + " x " + std::to_string(cell.height) + " m (column " +
                         std::to_string(cell.column) + ", row " + std::to_string(cell.row) + ")");
  const Frame& f = cell.frame;
  ControlPoints cp;
  // Centred across the width; up the face from the cell's bottom, or from its
  // origin when the cell has no height.
  cp.origin = f.origin - (width / 2) * f.along - (has_height ? height / 2 : 0.0) * f.up;
  cp.x_end = cp.origin + width * f.along;
  cp.y_end = has_height ? cp.origin + height * f.up : keep_size(box, 1, cp.origin, f.up);
  cp.z_end = keep_size(box, 2, cp.origin, f.normal);
  return map_box(box, cp);
}

}  // namespace procex
