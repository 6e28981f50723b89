#include "core/geom/chain_overlay.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <numeric>
#include <span>
#include <tuple>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/cross.h"
#include "core/geom/segment_distance.h"
#include "core/geom/point_grid.h"
#include "core/geom/predicates.h"
#include "core/geom/segment_intersections.h"

namespace procex {
namespace {

// A winding number per group, sorted by group, zeros left out.
using Cover = std::vector<std::pair<int, int>>;
using CoverView = std::span<const std::pair<int, int>>;

// sum = to + sign * from.
void add_cover(const Cover& to, CoverView from, int sign, Cover& sum) {
  sum.clear();
  sum.reserve(to.size() + from.size());
  std::size_t i = 0, j = 0;
  while (i < to.size() || j < from.size()) {
    if (j == from.size() || (i < to.size() && to[i].first < from[j].first)) {
      sum.push_back(to[i++]);
    } else if (i == to.size() || from[j].first < to[i].first) {
      sum.push_back({from[j].first, sign * from[j].second});
      ++j;
    } else {
      if (const int w = to[i].second + sign * from[j].second; w != 0) sum.push_back({to[i].first, w});
      ++i;
      ++j;
    }
  }
}

// Where the segments cut each other: for each segment the points lying on
// its inside, in no order. The segments are distinct point pairs.
std::vector<std::vector<std::uint32_t>> find_cuts(std::vector<glm::dvec2>& pts,
                                                  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& segments,
                                                  double near) {
  const std::size_t n = segments.size(), inputs = pts.size();
  // Candidates: segments and points (as segments of no length) near each
  // other.
  std::vector<Segment2> candidates;
  candidates.reserve(n + inputs);
  for (const auto& [u, v] : segments) candidates.push_back({pts[u], pts[v]});
  for (std::size_t i = 0; i < inputs; ++i) candidates.push_back({pts[i], pts[i]});

  std::vector<std::vector<std::uint32_t>> cuts(n);
  auto cut = [&](std::size_t s, std::uint32_t q) {
    const auto [u, v] = segments[s];
    if (q == u || q == v) return;
    const glm::dvec2 a = pts[u], d = pts[v] - a, p = pts[q];
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0.0 ? glm::dot(p - a, d) / len2 : 0.0;
    if (!(t > 0.0 && t < 1.0) || glm::length(a + t * d - p) > near || glm::length(p - a) <= near ||
        glm::length(p - pts[v]) <= near)
      return;
    cuts[s].push_back(q);
  };
  PointGrid grid(near);
  grid.reserve(inputs + inputs / 4);
  for (std::size_t i = 0; i < inputs; ++i) grid.add(pts[i], static_cast<std::uint32_t>(i));
  for_each_near_segment_pair(candidates, near, [&](std::size_t i, std::size_t j) {
    if (i >= n) return true;  // two points
    if (j >= n) {
      cut(i, static_cast<std::uint32_t>(j - n));
      return true;
    }
    const auto [iu, iv] = segments[i];
    const auto [ju, jv] = segments[j];
    if (iu == ju || iu == jv || iv == ju || iv == jv) return true;
    const glm::dvec2 a = pts[iu], b = pts[iv], c = pts[ju], d = pts[jv];
    // Only crossings make points; where an end touches the other segment, or
    // passes within `near` of it (where nearly parallel segments cross is ill
    // conditioned), that end cuts it instead.
    if (orient2d(a, b, c) * orient2d(a, b, d) >= 0 || orient2d(c, d, a) * orient2d(c, d, b) >= 0) return true;
    if (distance_to_segment(c, a, b) <= near || distance_to_segment(d, a, b) <= near ||
        distance_to_segment(a, c, d) <= near || distance_to_segment(b, c, d) <= near)
      return true;
    const glm::dvec2 p = a + (b - a) * (cross(c - a, d - c) / cross(b - a, d - c));
    std::uint32_t q;
    if (const auto same = grid.first_near(p)) {
      q = *same;
    } else {
      q = static_cast<std::uint32_t>(pts.size());
      pts.push_back(p);
      grid.add(p, q);
    }
    cut(i, q);
    cut(j, q);
    return true;
  });
  return cuts;
}

struct Arrangement {
  // Directed pieces: 2k runs from the lower to the higher point of undirected piece k, 2k + 1 back.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> piece;  // undirected, lower point first
  std::vector<std::pair<int, int>> nets;                        // every piece's net cover, one after another
  std::vector<std::size_t> net_from;                            // piece k's in nets: [net_from[k], net_from[k + 1])
  std::vector<int> next;                                        // directed piece -> next in its cycle
  std::vector<int> cycle_of;                                    // directed piece -> its cycle
  std::vector<int> cycled;                                      // the directed pieces, cycle by cycle
  std::vector<std::size_t> cycle_from;                          // cycle c's in cycled, like net_from

  std::uint32_t from(int d) const { return d % 2 == 0 ? piece[d / 2].first : piece[d / 2].second; }
  std::uint32_t to(int d) const { return from(d ^ 1); }
  // Per undirected piece, the windings that change across it, lower to higher.
  CoverView net(std::size_t k) const { return CoverView(nets).subspan(net_from[k], net_from[k + 1] - net_from[k]); }
  std::size_t cycles() const { return cycle_from.size() - 1; }
  // A cycle's directed pieces, the cell on their left.
  std::span<const int> cycle(std::size_t c) const {
    return std::span<const int>(cycled).subspan(cycle_from[c], cycle_from[c + 1] - cycle_from[c]);
  }
};

// The pieces across which some group's winding changes, and the cycles they
// bound: leaving a piece, turn to the next piece clockwise round its end, so
// the cell stays on the left.
Arrangement arrange(const ChainOverlay& o, const std::vector<OverlaySegment>& segments) {
  struct Crossing {  // one input piece: its points, lower first, its group and way
    std::uint32_t lo, hi;
    int group, way;
    bool operator<(const Crossing& x) const { return std::tie(lo, hi, group) < std::tie(x.lo, x.hi, x.group); }
  };
  std::vector<Crossing> all;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    if (segments[s].group < 0) continue;
    const auto& chain = o.pieces[s];
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const std::uint32_t u = chain[i], v = chain[i + 1];
      if (u != v) all.push_back({std::min(u, v), std::max(u, v), segments[s].group, u < v ? 1 : -1});
    }
  }
  std::sort(all.begin(), all.end());
  Arrangement a;
  a.net_from.push_back(0);
  Cover cover;
  for (std::size_t i = 0; i < all.size();) {
    cover.clear();
    std::size_t j = i;
    for (; j < all.size() && all[j].lo == all[i].lo && all[j].hi == all[i].hi; ++j) {
      if (cover.empty() || cover.back().first != all[j].group) cover.push_back({all[j].group, 0});
      cover.back().second += all[j].way;
    }
    std::erase_if(cover, [](const std::pair<int, int>& g) { return g.second == 0; });
    if (!cover.empty()) {
      a.piece.push_back({all[i].lo, all[i].hi});
      a.nets.insert(a.nets.end(), cover.begin(), cover.end());
      a.net_from.push_back(a.nets.size());
    }
    i = j;
  }
  const int directed = static_cast<int>(2 * a.piece.size());
  std::vector<double> angle(directed);
  std::vector<int> order(directed);
  for (int d = 0; d < directed; ++d) {
    const glm::dvec2 v = o.points[a.to(d)] - o.points[a.from(d)];
    angle[d] = std::atan2(v.y, v.x);
  }
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int x, int y) {
    return a.from(x) != a.from(y) ? a.from(x) < a.from(y) : angle[x] != angle[y] ? angle[x] < angle[y] : x < y;
  });
  std::vector<int> rank(directed), first(directed);  // position in order; where its point's run starts
  for (int i = 0; i < directed; ++i) {
    rank[order[i]] = i;
    first[order[i]] = i > 0 && a.from(order[i - 1]) == a.from(order[i]) ? first[order[i - 1]] : i;
  }
  a.next.assign(directed, -1);
  for (int d = 0; d < directed; ++d) {
    const int back = d ^ 1;  // leaves the end of d
    int i = rank[back];
    if (i == first[back]) {
      while (i + 1 < directed && a.from(order[i + 1]) == a.from(back)) ++i;  // wrap to the run's last
    } else {
      --i;
    }
    a.next[d] = order[i];
  }
  a.cycle_of.assign(directed, -1);
  a.cycled.reserve(directed);
  a.cycle_from.push_back(0);
  for (int d = 0; d < directed; ++d) {
    if (a.cycle_of[d] >= 0) continue;
    for (int x = d; a.cycle_of[x] < 0; x = a.next[x]) {
      a.cycle_of[x] = static_cast<int>(a.cycle_from.size() - 1);
      a.cycled.push_back(x);
    }
    a.cycle_from.push_back(a.cycled.size());
  }
  return a;
}

// The windings just left of directed piece d, counted along a ray from its
// middle going left: each piece the ray crosses adds its windings, signed by
// the way it passes round the ray's start.
Cover cover_left_of(const ChainOverlay& o, const Arrangement& a, int d) {
  const glm::dvec2 p = o.points[a.from(d)], q = o.points[a.to(d)];
  const glm::dvec2 m = 0.5 * (p + q), ray{p.y - q.y, q.x - p.x};
  Cover w, sum;
  for (std::size_t k = 0; k < a.piece.size(); ++k) {
    if (static_cast<int>(k) == d / 2) continue;
    const glm::dvec2 u = o.points[a.piece[k].first], v = o.points[a.piece[k].second];
    const double su = cross(ray, u - m), sv = cross(ray, v - m);
    // Half-open: a point on the ray's line counts as left of it.
    const int sign = su < 0.0 && sv >= 0.0 ? 1 : su >= 0.0 && sv < 0.0 ? -1 : 0;
    if (sign == 0) continue;
    const glm::dvec2 x = u + (v - u) * (su / (su - sv));
    if (glm::dot(x - m, ray) > 0.0) {
      add_cover(w, a.net(k), sign, sum);
      std::swap(w, sum);
    }
  }
  return w;
}

}  // namespace

ChainOverlay overlay_chains(std::vector<glm::dvec2> points, const std::vector<OverlaySegment>& segments,
                            double near) {
  ChainOverlay o;
  o.points = std::move(points);
  // Cut each distinct pair of points once, whichever way and however often it is given.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> distinct;
  std::vector<std::size_t> which(segments.size());
  {
    // (lower point, higher point, segment), sorted.
    std::vector<std::pair<std::uint64_t, std::size_t>> order(segments.size());
    for (std::size_t s = 0; s < segments.size(); ++s) {
      const auto [lo, hi] = std::minmax(segments[s].from, segments[s].to);
      order[s] = {std::uint64_t{lo} << 32 | hi, s};
    }
    std::sort(order.begin(), order.end());
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (i == 0 || order[i].first != order[i - 1].first)
        distinct.push_back({static_cast<std::uint32_t>(order[i].first >> 32), static_cast<std::uint32_t>(order[i].first)});
      which[order[i].second] = distinct.size() - 1;
    }
  }
  std::vector<std::vector<std::uint32_t>> cuts = find_cuts(o.points, distinct, near);
  for (std::size_t k = 0; k < distinct.size(); ++k) {
    const glm::dvec2 a = o.points[distinct[k].first], d = o.points[distinct[k].second] - a;
    auto& c = cuts[k];
    std::sort(c.begin(), c.end(), [&](std::uint32_t x, std::uint32_t y) {
      const double tx = glm::dot(o.points[x] - a, d), ty = glm::dot(o.points[y] - a, d);
      return tx != ty ? tx < ty : x < y;
    });
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  o.pieces.resize(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const auto& c = cuts[which[s]];
    auto& chain = o.pieces[s];
    chain.reserve(c.size() + 2);
    chain.push_back(segments[s].from);
    if (segments[s].from == distinct[which[s]].first) {
      chain.insert(chain.end(), c.begin(), c.end());
    } else {
      chain.insert(chain.end(), c.rbegin(), c.rend());
    }
    chain.push_back(segments[s].to);
  }

  const Arrangement a = arrange(o, segments);
  const std::size_t cycles = a.cycles();
  // Each connected part of the arrangement has one cycle round its outside
  // (clockwise: the least signed area). The windings there come from a ray;
  // every other cycle of the part is reached across pieces, whose net
  // windings say how much they change.
  std::vector<double> area(cycles, 0.0);
  for (std::size_t c = 0; c < cycles; ++c)
    for (int d : a.cycle(c)) area[c] += cross(o.points[a.from(d)], o.points[a.to(d)]);
  std::vector<std::uint32_t> parent(o.points.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [u, v] : a.piece) parent[root(u)] = root(v);
  std::map<std::uint32_t, std::size_t> outside;  // part -> its outside cycle
  for (std::size_t c = 0; c < cycles; ++c) {
    auto [it, fresh] = outside.try_emplace(root(a.from(a.cycle(c).front())), c);
    if (!fresh && area[c] < area[it->second]) it->second = c;
  }
  std::vector<Cover> cover(cycles);
  std::vector<char> known(cycles, 0);
  std::vector<std::size_t> queue;
  for (const auto& [part, c] : outside) {
    cover[c] = cover_left_of(o, a, a.cycle(c).front());
    known[c] = 1;
    queue.push_back(c);
  }
  for (std::size_t i = 0; i < queue.size(); ++i) {
    const std::size_t c = queue[i];
    for (int d : a.cycle(c)) {
      const std::size_t other = static_cast<std::size_t>(a.cycle_of[d ^ 1]);
      if (known[other]) continue;
      add_cover(cover[c], a.net(static_cast<std::size_t>(d / 2)), d % 2 == 0 ? -1 : 1, cover[other]);
      known[other] = 1;
      queue.push_back(other);
    }
  }

  for (std::size_t c = 0; c < cycles; ++c) {
    int winding = 0;
    for (const auto& [g, w] : cover[c]) winding += w;
    if (winding == 0) continue;
    OverlayCell cell;
    cell.winding = winding;
    for (const auto& [g, w] : cover[c])
      if ((w > 0) == (winding > 0)) {
        cell.owner = g;
        break;
      }
    for (int d : a.cycle(c)) cell.loop.push_back(a.from(d));
    o.cells.push_back(std::move(cell));
  }
  return o;
}

}  // namespace procex
