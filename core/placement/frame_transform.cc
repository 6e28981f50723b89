#include "core/placement/frame_transform.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "core/placement/placement_error.h"
#include "core/geom/tolerances.h"

namespace procex {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string frame_text(const Frame& f) {
  return "origin " + vector_text(f.origin) + ", along " + vector_text(f.along) + ", up " + vector_text(f.up) +
         ", normal " + vector_text(f.normal);
}

}  // namespace

glm::dmat4 frame_matrix(const Frame& frame) {
  const double e = kFrameOrthonormality;
  if (!finite(frame.origin) || !finite(frame.along) || !finite(frame.up) || !finite(frame.normal))
    throw PlacementError("the frame has a non-finite value: " + frame_text(frame));
  for (const glm::dvec3* axis : {&frame.along, &frame.up, &frame.normal})
    if (std::abs(glm::length(*axis) - 1.0) > e)
      throw PlacementError("the frame's axes must have length 1: " + frame_text(frame));
  if (std::abs(glm::dot(frame.along, frame.up)) > e || std::abs(glm::dot(frame.along, frame.normal)) > e ||
      std::abs(glm::dot(frame.up, frame.normal)) > e)
    throw PlacementError("the frame's axes must be perpendicular: " + frame_text(frame));
  if (glm::length(glm::cross(frame.along, frame.up) - frame.normal) > e)
    throw PlacementError("the frame must be right-handed (cross(along, up) == normal): " + frame_text(frame));
  return glm::dmat4(glm::dvec4(frame.along, 0.0), glm::dvec4(frame.up, 0.0), glm::dvec4(frame.normal, 0.0),
                    glm::dvec4(frame.origin, 1.0));
}

glm::dmat4 place_at(const Frame& frame, const FramePlacement& placement) {
  const glm::dvec3& s = placement.scale;
  if (!finite(s) || s.x == 0.0 || s.y == 0.0 || s.z == 0.0)
    throw PlacementError("a placement scale must be finite and non-zero on every axis, not " + vector_text(s));
  if (!finite(placement.pivot) || !finite(placement.offset))
    throw PlacementError("a placement's pivot and offset must be finite: pivot " + vector_text(placement.pivot) +
                         ", offset " + vector_text(placement.offset));
  glm::dmat4 local(1.0);  // translate(offset) * scale(s) * translate(-pivot), written out
  for (int k = 0; k < 3; ++k) local[k][k] = s[k];
  local[3] = glm::dvec4(placement.offset - s * placement.pivot, 1.0);
  return frame_matrix(frame) * local;
}

Frame orthonormal_frame(const glm::dvec3& origin, const glm::dvec3& along, const glm::dvec3& up) {
  const double a = glm::length(along);
  if (!(a > 0.0) || !std::isfinite(a)) throw PlacementError("a frame needs a non-zero finite along direction, not " + vector_text(along));
  Frame f;
  f.origin = origin;
  f.along = along / a;
  const glm::dvec3 u = up - glm::dot(up, f.along) * f.along;
  const double ul = glm::length(u);
  if (!(ul > kFrameOrthonormality * glm::length(up)) || !std::isfinite(ul))
    throw PlacementError("a frame's up direction " + vector_text(up) + " must not be zero or parallel to along " +
                         vector_text(along));
  f.up = u / ul;
  f.normal = glm::cross(f.along, f.up);
  return f;
}

}  // namespace procex
