// The seeded corpus test's house profiles, shared with the regressions it
// found: every kind of segment (vertical walls, horizontal runs out (soffits)
// and in (ledges), mansard breaks, a fascia, an outward lean).
#pragma once

#include <vector>

#include "core/geom/profile.h"

namespace procex {

// Indices into house_profiles().
enum HouseProfile { kSoffit, kLedge, kMansard, kFascia, kLean, kHouseProfileCount };

inline std::vector<Profile> house_profiles() {
  return {
      {"soffit", {{0, 0}, {0, 3}, {0.5, 3}, {-4.5, 8}}, {"wall", "soffit", "roof"}},
      {"ledge", {{0, 0}, {0, 3}, {-1, 3}, {-1, 6}, {-6, 11}}, {"wall", "ledge", "wall", "roof"}},
      {"mansard", {{0, 0}, {0, 3}, {-1, 6}, {-4, 7}}, {"wall", "mansard", "roof"}},
      {"fascia", {{0, 0}, {0, 3}, {0.4, 3}, {0.4, 3.2}, {-4, 7}}, {"wall", "soffit", "fascia", "roof"}},
      {"lean", {{0, 0}, {0, 3}, {0.6, 4}, {-3, 8}}, {"wall", "overhang", "roof"}},
  };
}

}  // namespace procex
