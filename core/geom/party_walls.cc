#include "core/geom/party_walls.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/nesting.h"

namespace procex {
namespace {

struct Edge {
  glm::dvec2 a, b;
  glm::dvec2 out;  // unit outward normal
  std::size_t plan;
  std::int32_t id;
};

// Two edges within 10 degrees of parallel (either direction) run along each other.
constexpr double kParallelSine = 0.17364817766693033;  // sin(10 degrees)

}  // namespace

std::vector<std::vector<std::int32_t>> party_edges(const std::vector<PlanLoops>& plans, double distance) {
  std::vector<Edge> edges;
  glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
  double total = 0;
  for (std::size_t p = 0; p < plans.size(); ++p) {
    std::int32_t id = 0;
    const LoopNesting nesting = loop_nesting(plans[p]);
    for (std::size_t li = 0; li < plans[p].size(); ++li) {
      const auto& loop = plans[p][li];
      // Material lies left of a counter-clockwise outer loop's edges and of a clockwise hole's.
      const double side = (twice_signed_area(loop) > 0) != (nesting.depth[li] % 2 == 1) ? 1.0 : -1.0;
      for (std::size_t k = 0; k < loop.size(); ++k, ++id) {
        Edge e{loop[k], loop[(k + 1) % loop.size()], {}, p, id};
        const glm::dvec2 d = e.b - e.a;
        const double length = glm::length(d);
        if (!std::isfinite(length) || !(length > 0)) continue;
        e.out = side * glm::dvec2(d.y, -d.x) / length;
        lo = glm::min(lo, glm::min(e.a, e.b)), hi = glm::max(hi, glm::max(e.a, e.b));
        total += length;
        edges.push_back(e);
      }
    }
  }
  std::vector<std::vector<std::int32_t>> out(plans.size());
  if (edges.empty()) return out;
  // Cells about the mean edge length (at most a million across the data).
  // An edge is listed in the cells of points half a cell apart along it. A
  // point within `distance` (at most a quarter cell) of edge e is within half
  // a cell of one of e's points, so the edges near e are listed in the cells
  // next to those of e's points (reach 1). An edge longer than kMaxSteps
  // steps is compared with every edge.
  constexpr std::int64_t kMaxSteps = 4096;
  const double cell = std::max({total / static_cast<double>(edges.size()), 4 * distance,
                                1e-6 * std::max(hi.x - lo.x, hi.y - lo.y), 1e-9});
  auto steps = [&](const Edge& e) { return static_cast<std::int64_t>(std::ceil(2 * glm::length(e.b - e.a) / cell)); };
  auto is_long = [&](const Edge& e) { return steps(e) > kMaxSteps; };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  std::vector<std::size_t> long_edges;
  auto cells = [&](const Edge& e, std::int64_t reach, auto&& visit) {
    const std::int64_t n = std::max<std::int64_t>(1, steps(e));
    std::vector<std::uint64_t> keys;
    for (std::int64_t k = 0; k <= n; ++k) {
      const glm::dvec2 p = e.a + (e.b - e.a) * (static_cast<double>(k) / static_cast<double>(n));
      const auto x = static_cast<std::int64_t>(std::floor((p.x - lo.x) / cell));
      const auto y = static_cast<std::int64_t>(std::floor((p.y - lo.y) / cell));
      for (std::int64_t dx = -reach; dx <= reach; ++dx)
        for (std::int64_t dy = -reach; dy <= reach; ++dy)
          keys.push_back(static_cast<std::uint64_t>(x + dx + 1) << 32 | static_cast<std::uint32_t>(y + dy + 1));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (const auto& key : keys) visit(key);
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (is_long(edges[i]))
      long_edges.push_back(i);
    else
      cells(edges[i], 0, [&](auto key) { grid[key].push_back(i); });
  }

  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    const double length = glm::length(e.b - e.a);
    const glm::dvec2 u = (e.b - e.a) / length, n(-u.y, u.x);
    std::vector<std::size_t> near = long_edges;
    if (is_long(e)) {
      for (std::size_t j = 0; j < edges.size(); ++j) near.push_back(j);
    } else {
      cells(e, 1, [&](auto key) {
        if (const auto it = grid.find(key); it != grid.end()) near.insert(near.end(), it->second.begin(), it->second.end());
      });
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    // The stretches of e that other plans' edges run along, as [from, to] along it.
    std::vector<std::pair<double, double>> covered;
    for (std::size_t j : near) {
      const Edge& f = edges[j];
      if (f.plan == e.plan || glm::dot(e.out, f.out) >= 0) continue;
      const glm::dvec2 d = f.b - f.a;
      const double fl = glm::length(d);
      if (!(fl > 0) || std::abs(u.x * d.y - u.y * d.x) > kParallelSine * fl) continue;
      if (std::abs(glm::dot(f.a - e.a, n)) > distance || std::abs(glm::dot(f.b - e.a, n)) > distance) continue;
      const double s = glm::dot(f.a - e.a, u), t = glm::dot(f.b - e.a, u);
      const double from = std::max(0.0, std::min(s, t)), to = std::min(length, std::max(s, t));
      if (to > from) covered.emplace_back(from, to);
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
