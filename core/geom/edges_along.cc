#include "core/geom/edges_along.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/nesting.h"

namespace procex {
namespace {

// Two lines within 10 degrees of parallel (either direction) run along each other.
constexpr double kParallelSine = 0.17364817766693033;  // sin(10 degrees)

// Cells about the mean piece length (at most a million across the data). A
// piece is listed in the cells of points half a cell apart along it. A point
// within `distance` (at most a quarter cell) of an edge is within half a cell
// of one of the edge's points, so the pieces near it are listed in the cells
// next to those of its points (reach 1). A segment longer than kMaxSteps steps
// is compared with everything.
class Grid {
 public:
  Grid(const std::vector<LinePiece>& pieces, double distance) {
    glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
    double total = 0;
    for (const LinePiece& p : pieces) {
      lo = glm::min(lo, glm::min(p.a, p.b)), hi = glm::max(hi, glm::max(p.a, p.b));
      total += glm::length(p.b - p.a);
    }
    if (pieces.empty()) return;
    origin_ = lo;
    cell_ = std::max({total / static_cast<double>(pieces.size()), 4 * distance, 1e-6 * std::max(hi.x - lo.x, hi.y - lo.y), 1e-9});
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (is_long(pieces[i].a, pieces[i].b))
        long_.push_back(i);
      else
        cells(pieces[i].a, pieces[i].b, 0, [&](std::uint64_t key) { cells_[key].push_back(i); });
    }
    count_ = pieces.size();
  }

  // The pieces that may lie within `distance` of the segment a-b (and more), sorted.
  std::vector<std::size_t> near(glm::dvec2 a, glm::dvec2 b) const {
    std::vector<std::size_t> found = long_;
    if (is_long(a, b)) {
      for (std::size_t j = 0; j < count_; ++j) found.push_back(j);
    } else if (count_ > 0) {
      cells(a, b, 1, [&](std::uint64_t key) {
        if (const auto it = cells_.find(key); it != cells_.end()) found.insert(found.end(), it->second.begin(), it->second.end());
      });
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }

 private:
  static constexpr std::int64_t kMaxSteps = 4096;
  std::int64_t steps(glm::dvec2 a, glm::dvec2 b) const {
    return static_cast<std::int64_t>(std::ceil(std::min(2 * glm::length(b - a) / cell_, 1e18)));
  }
  bool is_long(glm::dvec2 a, glm::dvec2 b) const { return !(steps(a, b) <= kMaxSteps); }
  // Cell coordinates, kept where the key packs them (a point that far off is in no listed cell anyway).
  std::int64_t coordinate(double v, double o) const {
    return static_cast<std::int64_t>(std::clamp(std::floor((v - o) / cell_), -1e9, 1e9));
  }
  template <class Visit>
  void cells(glm::dvec2 a, glm::dvec2 b, std::int64_t reach, Visit&& visit) const {
    const std::int64_t n = std::max<std::int64_t>(1, steps(a, b));
    std::vector<std::uint64_t> keys;
    for (std::int64_t k = 0; k <= n; ++k) {
      const glm::dvec2 p = a + (b - a) * (static_cast<double>(k) / static_cast<double>(n));
      const std::int64_t x = coordinate(p.x, origin_.x), y = coordinate(p.y, origin_.y);
      for (std::int64_t dx = -reach; dx <= reach; ++dx)
        for (std::int64_t dy = -reach; dy <= reach; ++dy)
          keys.push_back(static_cast<std::uint64_t>(x + dx + (1ll << 31)) << 32 | static_cast<std::uint32_t>(y + dy + (1ll << 31)));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (const std::uint64_t key : keys) visit(key);
  }
  glm::dvec2 origin_{0.0};
  double cell_ = 1.0;
  std::size_t count_ = 0;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
  std::vector<std::size_t> long_;
};

}  // namespace

std::vector<PlanEdge> plan_edges(const std::vector<PlanLoops>& plans) {
  std::vector<PlanEdge> edges;
  for (std::size_t p = 0; p < plans.size(); ++p) {
    std::int32_t id = 0;
    const LoopNesting nesting = loop_nesting(plans[p]);
    for (std::size_t li = 0; li < plans[p].size(); ++li) {
      const auto& loop = plans[p][li];
      // Material lies left of a counter-clockwise outer loop's edges and of a clockwise hole's.
      const double side = (twice_signed_area(loop) > 0) != (nesting.depth[li] % 2 == 1) ? 1.0 : -1.0;
      for (std::size_t k = 0; k < loop.size(); ++k, ++id) {
        PlanEdge e{loop[k], loop[(k + 1) % loop.size()], {}, p, id};
        const glm::dvec2 d = e.b - e.a;
        const double length = glm::length(d);
        if (!std::isfinite(length) || !(length > 0)) continue;
        e.out = side * glm::dvec2(d.y, -d.x) / length;
        edges.push_back(e);
      }
    }
  }
  return edges;
}

std::vector<std::vector<std::int32_t>> edges_along(std::size_t plans, const std::vector<PlanEdge>& edges,
                                                   const std::vector<LinePiece>& pieces, double distance,
                                                   LineTest counts, const void* context) {
  const Grid grid(pieces, distance);
  std::vector<std::vector<std::int32_t>> out(plans);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const PlanEdge& e = edges[i];
    const double length = glm::length(e.b - e.a);
    const glm::dvec2 u = (e.b - e.a) / length, n(-u.y, u.x);
    // The stretches of e that pieces run along, as [from, to] along it.
    std::vector<std::pair<double, double>> covered;
    for (const std::size_t j : grid.near(e.a, e.b)) {
      const LinePiece& f = pieces[j];
      const glm::dvec2 d = f.b - f.a;
      const double fl = glm::length(d);
      if (!(fl > 0) || std::abs(u.x * d.y - u.y * d.x) > kParallelSine * fl) continue;
      // The piece over e's span (parallel within 10 degrees: s and t differ),
      // and how far off e's line it is at either end of that.
      const double s = glm::dot(f.a - e.a, u), t = glm::dot(f.b - e.a, u);
      const double from = std::max(0.0, std::min(s, t)), to = std::min(length, std::max(s, t));
      if (!(to > from)) continue;
      const double hs = glm::dot(f.a - e.a, n), ht = glm::dot(f.b - e.a, n);
      const auto offset = [&](double at) { return hs + (ht - hs) * (at - s) / (t - s); };
      if (std::abs(offset(from)) > distance || std::abs(offset(to)) > distance) continue;
      if (!counts(e, f, glm::dot(n, e.out) * offset((from + to) / 2), context)) continue;
      covered.emplace_back(from, to);
    }
    std::sort(covered.begin(), covered.end());
    double along = 0, reach = 0;
    for (const auto& [from, to] : covered) {
      along += std::max(0.0, to - std::max(from, reach));
      reach = std::max(reach, to);
    }
    if (along >= 0.5 * length) out[e.plan].push_back(e.id);
  }
  for (auto& ids : out) std::sort(ids.begin(), ids.end());
  return out;
}

}  // namespace procex
