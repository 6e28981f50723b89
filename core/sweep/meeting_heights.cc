#include "core/sweep/meeting_heights.h"

#include <cmath>

namespace procex::engine {

// Without branches, so the loop vectorizes (wider where the CPU allows: add,
// multiply, divide and compare round the same at any width, and no fused
// multiply-add is enabled, so every width gives the same bits).
[[gnu::target_clones("avx2", "default")]] void meeting_heights(const double* nx, const double* ny, const double* kk,
                                                               const double* cc, std::size_t n, const CornerPath& path,
                                                               double* meet) {
  // Copied: meet[] could alias the path, which would keep the loop from vectorizing.
  const glm::dvec2 p = path.p, v = path.v;
  const double z = path.z, earliest = path.earliest, cap = path.cap, on = path.on;
  // A rate this small moves the corner off a plane by `along` of its own travel.
  const double drift = path.along * (std::abs(v.x) + std::abs(v.y));
  const bool outward = path.outward;
  for (std::size_t j = 0; j < n; ++j) {
    // Signed distance from the edge's line changes at `rate`: a corner inside
    // meets it when the distance falls to zero, a corner of another polygon
    // growing towards it (from outside) when it rises to zero.
    const double rate = nx[j] * v.x + ny[j] * v.y - kk[j];
    const double distance = nx[j] * p.x + ny[j] * p.y - (cc[j] + kk[j] * z);
    const double at = z - distance / (rate + static_cast<double>(rate == 0.0));
    // A meeting point below the sweep plane means the planes diverge from here.
    const bool meets = (rate < 0.0) | ((rate > 0.0) & outward);
    const double off = std::abs(distance), drifts = std::abs(rate);
    const bool runs_along = (off <= on) & (drifts <= drift);
    meet[j] = (meets & !runs_along & !(at < earliest) & !(at > cap)) ? at : HUGE_VAL;
  }
}

}  // namespace procex::engine
