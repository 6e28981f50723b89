// Where a moving corner meets each of many planes: the sweep's inner loop.
// One function for every caller, so that a split worked out by testing every
// plane and one worked out through an index (PlaneIndex) have the same bits.
#pragma once

#include <cmath>
#include <cstddef>

#include <glm/vec2.hpp>

namespace procex::engine {

// A corner at p at height z, moving by v per unit of height, and which of its
// meetings count: none below `earliest` or above `cap`; with `outward` it also
// meets planes from outside. A plane it runs along, within `on` of it where it
// is and drifting off it by at most `along` of the plan distance it travels,
// it never meets: it moves in that plane, and where it comes to the plane's
// edge it comes to the edge's end, another corner's event. Taken for a split,
// the meeting of two such planes is wherever rounding puts it (a wall beside a
// collinear wall, moved far from the origin: angles seed 8865).
struct CornerPath {
  glm::dvec2 p{0.0}, v{0.0};
  double z = 0.0, earliest = 0.0, cap = HUGE_VAL;
  bool outward = false;
  double on = 0.0, along = 0.0;
};

// The height where the corner meets each plane n.x - k z = c, or HUGE_VAL
// where it does not (the planes diverge, it runs along the plane, or the
// meeting does not count). Elementwise: meet[j] depends only on plane j.
void meeting_heights(const double* nx, const double* ny, const double* kk, const double* cc, std::size_t n,
                     const CornerPath& path, double* meet);

}  // namespace procex::engine
