#include "app/studio/editor/plan_edit.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>

#include "core/geom/error.h"
#include "core/geom/footprint.h"
#include "core/geom/nesting.h"
#include "core/geom/prepare.h"

namespace procex::studio {

namespace {

std::vector<glm::dvec2> to_dvec(const std::vector<Vec2>& pts) {
  std::vector<glm::dvec2> out;
  out.reserve(pts.size());
  for (const Vec2& p : pts) out.push_back({p.x, p.y});
  return out;
}

std::string loop_name(int loop) { return loop >= 1 ? "hole " + std::to_string(loop) : "outer loop"; }

double distance_to_edges(glm::dvec2 p, const std::vector<glm::dvec2>& loop) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()], ab = b - a;
    const double len2 = ab.x * ab.x + ab.y * ab.y;
    const double t = len2 > 0 ? std::clamp(((p.x - a.x) * ab.x + (p.y - a.y) * ab.y) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(p.x - (a.x + t * ab.x), p.y - (a.y + t * ab.y)));
  }
  return best;
}

}  // namespace

std::optional<PlanIssue> check_plan(const std::vector<Vec2>& outer, const PlanLoops& holes) {
  std::vector<std::vector<glm::dvec2>> loops = {to_dvec(outer)};
  for (const auto& h : holes) loops.push_back(to_dvec(h));
  try {
    (void)prepare_footprint(make_footprint(loops, 45.0));
  } catch (const InputError& e) {
    std::string where = e.loop() >= 0 ? loop_name(e.loop()) : "plan";
    if (e.vertex() >= 0) where += ", vertex " + std::to_string(e.vertex());
    return PlanIssue{where + ": " + e.what(), e.loop(), e.vertex()};
  }
  // Loops that neither cross nor touch: a hole is inside a loop when any of its corners is.
  for (int k = 1; k < static_cast<int>(loops.size()); ++k) {
    const auto& corner = loops[static_cast<std::size_t>(k)][0];
    if (!point_in_loop(corner, loops[0]))
      return PlanIssue{loop_name(k) + ": lies outside the outer loop (it would be a second building, not a courtyard)", k, 0};
    for (int j = 1; j < static_cast<int>(loops.size()); ++j)
      if (j != k && point_in_loop(corner, loops[static_cast<std::size_t>(j)]))
        return PlanIssue{loop_name(k) + ": lies inside " + loop_name(j) + " (a building inside a courtyard needs its own footprint)", k, 0};
  }
  return std::nullopt;
}

std::vector<Vec2> hole_inside(const std::vector<Vec2>& outer, const PlanLoops& holes) {
  const std::vector<glm::dvec2> loop = to_dvec(outer);
  if (loop.size() < 3) return {};
  std::vector<std::vector<glm::dvec2>> others;
  for (const auto& h : holes)
    if (h.size() >= 3) others.push_back(to_dvec(h));
  glm::dvec2 lo = loop[0], hi = loop[0];
  for (const glm::dvec2& p : loop) lo = glm::min(lo, p), hi = glm::max(hi, p);
  // The grid point deepest inside, away from the holes too: a square there stays clear of every edge.
  constexpr int kSteps = 24;
  glm::dvec2 best{0.0};
  double best_d = 0;
  for (int i = 1; i < kSteps; ++i)
    for (int j = 1; j < kSteps; ++j) {
      const glm::dvec2 p = lo + (hi - lo) * glm::dvec2(i, j) / static_cast<double>(kSteps);
      if (!point_in_loop(p, loop)) continue;
      double d = distance_to_edges(p, loop);
      for (const auto& h : others) d = point_in_loop(p, h) ? 0.0 : std::min(d, distance_to_edges(p, h));
      if (d > best_d) best_d = d, best = p;
    }
  if (best_d <= 0) return {};
  const double h = best_d * 0.5;  // half the side: the square's corners stay 0.29 d from the edges
  return {{best.x - h, best.y - h}, {best.x - h, best.y + h}, {best.x + h, best.y + h}, {best.x + h, best.y - h}};  // clockwise
}

}  // namespace procex::studio
