// Where a moving corner meets each of many planes: the sweep's inner loop.
// One function for every caller, so that a split worked out by testing every
// plane and one worked out through an index (PlaneIndex) have the same bits.
#pragma once

#include <cstddef>

#include <glm/vec2.hpp>

namespace procex::engine {

// The height where a corner at p (at height z, moving by v per unit of
// height) meets each plane n.x - k z = c, or HUGE_VAL where it does not (the
// planes diverge, or the meeting is below `earliest` or above `cap`); with
// `outward`, corners also meet planes from outside. Elementwise: meet[j]
// depends only on plane j.
void meeting_heights(const double* nx, const double* ny, const double* kk, const double* cc, std::size_t n,
                     glm::dvec2 p, glm::dvec2 v, double z, double earliest, double cap, bool outward, double* meet);

}  // namespace procex::engine
