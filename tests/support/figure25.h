// The paper's fig. 25 analogue, shared by the gallery test and the profile
// benchmark: six blocks, each with a courtyard holding an island and a second
// courtyard, 24 loops of 23 vertices (552), three profiles by edge: every
// edge's eave steps out at 3 m (by 0.3, 0.5 or 0.8), then a roof or a mansard.
#pragma once

#include <cmath>
#include <vector>

#include "core/geom/footprint.h"

namespace procex::testing {

inline Footprint figure25_analogue() {
  auto ring = [](glm::dvec2 centre, double r, bool clockwise) {
    std::vector<glm::dvec2> pts;
    for (int i = 0; i < 23; ++i) {
      const double a = 2 * M_PI * i / 23 * (clockwise ? -1 : 1);
      pts.push_back(centre + r * (1.0 + 0.04 * std::sin(5.0 * a)) * glm::dvec2{std::cos(a), std::sin(a)});
    }
    return pts;
  };
  std::vector<std::vector<glm::dvec2>> loops;
  for (int b = 0; b < 6; ++b) {
    const glm::dvec2 c{100.0 * (b % 3), 100.0 * (b / 3)};
    loops.push_back(ring(c, 40, false));
    loops.push_back(ring(c + glm::dvec2{-12, 0}, 20, true));  // courtyard
    loops.push_back(ring(c + glm::dvec2{-12, 0}, 8, false));  // island in it
    loops.push_back(ring(c + glm::dvec2{22, 14}, 6, true));   // a small courtyard
  }
  Footprint fp = make_footprint(loops, 45.0);
  fp.profiles = {{"soffit", {{0, 0}, {0, 3}, {0.5, 3}, {-10, 13.5}}, {"wall", "soffit", "roof"}},
                 {"mansard", {{0, 0}, {0, 3}, {0.3, 3}, {-1, 6}, {-4, 7}}, {"wall", "soffit", "mansard", "roof"}},
                 {"deep eave", {{0, 0}, {0, 3}, {0.8, 3}, {-6, 9}}, {"wall", "soffit", "roof"}}};
  int k = 0;
  for (Loop& loop : fp.loops)
    for (EdgeSpec& e : loop.edges) e.profile = k++ % 3;
  return fp;
}

}  // namespace procex::testing
