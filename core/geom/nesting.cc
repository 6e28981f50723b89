#include "core/geom/nesting.h"

#include <algorithm>
#include <limits>

#include <glm/common.hpp>

#include "core/geom/predicates.h"

namespace procex {

double twice_signed_area(const std::vector<glm::dvec2>& loop) {
  double a = 0.0;
  const std::size_t n = loop.size();
  if (n == 0) return a;
  // Relative to the first point, which keeps the sum accurate far from the origin.
  const glm::dvec2 o = loop[0];
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const glm::dvec2 p = loop[k] - o, q = loop[k + 1] - o;
    a += p.x * q.y - p.y * q.x;
  }
  return a;
}

bool point_in_loop(const glm::dvec2& p, const std::vector<glm::dvec2>& loop) {
  bool inside = false;
  const std::size_t n = loop.size();
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec2& a = loop[k];
    const glm::dvec2& b = loop[(k + 1) % n];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    // The edge crosses the horizontal line through p; is the crossing right of p?
    const int o = orient2d(a, b, p);
    if (b.y > a.y ? o > 0 : o < 0) inside = !inside;
  }
  return inside;
}

LoopNesting loop_nesting(const std::vector<std::vector<glm::dvec2>>& loops) {
  const std::size_t n = loops.size();
  struct Box {
    glm::dvec2 lo, hi;
  };
  std::vector<Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) {
    Box b{glm::dvec2(std::numeric_limits<double>::infinity()), glm::dvec2(-std::numeric_limits<double>::infinity())};
    for (const auto& p : loops[i]) {
      b.lo = glm::min(b.lo, p);
      b.hi = glm::max(b.hi, p);
    }
    boxes[i] = b;
  }
  LoopNesting out{std::vector<int>(n, 0), std::vector<int>(n, -1)};
  std::vector<std::vector<int>> containers(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (loops[i].empty()) continue;
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j || loops[j].size() < 3) continue;
      const Box &bi = boxes[i], &bj = boxes[j];
      if (bi.lo.x < bj.lo.x || bi.lo.y < bj.lo.y || bi.hi.x > bj.hi.x || bi.hi.y > bj.hi.y) continue;
      if (point_in_loop(loops[i][0], loops[j])) containers[i].push_back(static_cast<int>(j));
    }
    out.depth[i] = static_cast<int>(containers[i].size());
  }
  for (std::size_t i = 0; i < n; ++i)
    for (int j : containers[i])
      if (out.depth[j] == out.depth[i] - 1) out.parent[i] = j;
  return out;
}

}  // namespace procex
