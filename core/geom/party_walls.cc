#include "core/geom/party_walls.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/nesting.h"
#include <glm/ext/vector_int2_sized.hpp>

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
  // Cells about the mean edge length (at most a million across the data):
  // each edge is listed in the cells its bounds, grown by `distance`, touch;
  // an edge over more than kMaxCells of them is compared with every edge.
  constexpr std::int64_t kMaxCells = 64;
  const double cell = std::max({total / static_cast<double>(edges.size()), 4 * distance,
                                1e-6 * std::max(hi.x - lo.x, hi.y - lo.y), 1e-9});
  auto cell_of = [&](double v, double origin) { return static_cast<std::int64_t>(std::floor((v - origin) / cell)); };
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>> grid;
  std::vector<std::size_t> long_edges;
  auto span = [&](const Edge& e) {
    const glm::dvec2 l = glm::min(e.a, e.b) - distance, h = glm::max(e.a, e.b) + distance;
    return std::pair{glm::i64vec2(cell_of(l.x, lo.x), cell_of(l.y, lo.y)), glm::i64vec2(cell_of(h.x, lo.x), cell_of(h.y, lo.y))};
  };
  auto is_long = [&](const Edge& e) {
    const auto [l, h] = span(e);
    return (h.x - l.x + 1) * (h.y - l.y + 1) > kMaxCells;
  };
  auto cells = [&](const Edge& e, auto&& visit) {
    const auto [l, h] = span(e);
    for (std::int64_t x = l.x; x <= h.x; ++x)
      for (std::int64_t y = l.y; y <= h.y; ++y) visit(std::pair{x, y});
  };
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (is_long(edges[i]))
      long_edges.push_back(i);
    else
      cells(edges[i], [&](auto key) { grid[key].push_back(i); });
  }

  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    const double length = glm::length(e.b - e.a);
    const glm::dvec2 u = (e.b - e.a) / length, n(-u.y, u.x);
    std::vector<std::size_t> near = long_edges;
    if (is_long(e)) {
      for (std::size_t j = 0; j < edges.size(); ++j) near.push_back(j);
    } else {
      cells(e, [&](auto key) {
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
