#include "core/geom/convex_partition.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/horizontal_rays.h"
#include "core/geom/point_tree.h"
#include "core/geom/predicates.h"
#include "core/geom/tolerances.h"

namespace procex {

namespace {

using Index = std::uint32_t;
constexpr Index kNone = std::numeric_limits<Index>::max();

// A vertex of the shrinking ring that the ear clipper walks. After bridging,
// one input vertex can appear as two nodes (both ends of a bridge).
struct Node {
  Index vertex;
  Index prev, next;
  bool removed = false;
};

// Whether a -> b -> c runs straight on or back along itself up to rounding:
// a relative turn below kStraightTurnSine, or a cross product no larger than
// the last bits of the coordinates can make (a grid plan rotated and moved to
// (5e5, 5e6) puts vertices of one grid line 1e-11 off it, relative).
bool straight_up_to_rounding(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const glm::dvec2 u = b - a, w = c - b;
  const double lu = glm::length(u), lw = glm::length(w);
  const double coordinate = std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y), std::abs(c.x),
                                      std::abs(c.y)});
  const double rounding = 8.0 * std::numeric_limits<double>::epsilon() * coordinate;
  return std::abs(u.x * w.y - u.y * w.x) <= kStraightTurnSine * lu * lw + rounding * (lu + lw);
}

// Whether s lies on the segment from a to c up to rounding, strictly between
// its ends. Vertices of a rotated grid plan on one line in exact terms are
// not on it in floating point: to the exact predicates one can lie a hair
// outside an ear whose new edge passes through it, and clipping that ear
// runs the ring back over it (angles seed 3650: a hole's collinear vertices
// on the line from another hole's corner; the base face's pieces overlapped).
bool between_up_to_rounding(const glm::dvec2& a, const glm::dvec2& s, const glm::dvec2& c) {
  return glm::dot(s - a, c - s) > 0.0 && straight_up_to_rounding(a, s, c);
}

// Turn at b on the way a -> b -> c: +1 left, -1 right, 0 straight on, and
// 2 for a reversal (c back along b -> a), which is never convex. Straight and
// back up to rounding count as such: a piece cut there (vertices of holes on
// one grid line of a rotated plan) would have no area.
int turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  if (straight_up_to_rounding(a, b, c)) return glm::dot(b - a, c - b) > 0.0 ? 0 : 2;
  return orient2d(a, b, c);
}

bool convex_turn(int t) { return t == 0 || t == 1; }

// Whether a loop of three or more vertices makes an allowed turn at each.
template <class Allowed>
bool every_turn(const std::vector<glm::dvec2>& loop, Allowed allowed) {
  const std::size_t n = loop.size();
  if (n < 3) return false;
  for (std::size_t k = 0; k < n; ++k)
    if (!allowed(turn(loop[(k + n - 1) % n], loop[k], loop[(k + 1) % n]))) return false;
  return true;
}

// Where the ray from m to +x leaves through edge a -> b of the ring, if it
// does at or right of m: the outer ring is counter-clockwise, so from inside
// the ray leaves through an edge going upwards.
std::optional<double> ray_exit(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& m) {
  if (!(a.y <= m.y && m.y <= b.y && a.y != b.y)) return std::nullopt;
  const double x = a.x + (m.y - a.y) * (b.x - a.x) / (b.y - a.y);
  if (x < m.x) return std::nullopt;
  return x;
}

// The end of the edge a hole's bridge goes to: the end the ray hits, or else
// the one further right.
template <class End>
End bridge_end(const glm::dvec2& a, const glm::dvec2& b, double x, const glm::dvec2& m, End from, End to) {
  if (x == a.x && a.y == m.y) return from;
  if (x == b.x && b.y == m.y) return to;
  return a.x > b.x ? from : to;
}

// How a vertex q inside the triangle (m, hit, end) hides the end from m: the
// bridge goes to the one nearest the ray's direction, then nearest m. None
// where q lies outside the triangle. A vertex on the side from m to the end
// up to rounding, not exactly, hides it too: the bridge past it would run
// along the ring's own edge there (a cap's hole and outer loop with edges on
// one plane's line, 1e-15 off it: a piece of negative area, and the cap's
// pieces overlapped; tests/data/generated_random_polygons_angles_493.geojson).
struct Hiding {
  double tan, dist;
  bool operator<(const Hiding& o) const { return tan < o.tan || (tan == o.tan && dist < o.dist); }
  bool operator==(const Hiding& o) const { return tan == o.tan && dist == o.dist; }
};
std::optional<Hiding> hiding(const glm::dvec2 (&tri)[3], bool ccw, const glm::dvec2& q) {
  const int o1 = orient2d(tri[0], tri[1], q), o2 = orient2d(tri[1], tri[2], q), o3 = orient2d(tri[2], tri[0], q);
  const bool inside = ccw ? (o1 >= 0 && o2 >= 0 && o3 >= 0) : (o1 <= 0 && o2 <= 0 && o3 <= 0);
  if (!inside && !between_up_to_rounding(tri[0], q, tri[2])) return std::nullopt;
  const glm::dvec2& m = tri[0];
  const double dx = q.x - m.x;
  return Hiding{dx > 0.0 ? std::abs(q.y - m.y) / dx : std::numeric_limits<double>::infinity(), glm::dot(q - m, q - m)};
}

// Members of {0, ..., n - 1}, the first at or after a place found in a few
// word scans: a bit a member, and above them a bit a word that holds any.
class Places {
 public:
  explicit Places(std::size_t n = 0) {
    do {
      n = (n + 63) / 64;
      levels_.emplace_back(n, 0);
    } while (n > 1);
  }

  void insert(std::size_t i) {
    for (auto& level : levels_) {
      std::uint64_t& word = level[i / 64];
      const bool had = word != 0;
      word |= std::uint64_t{1} << (i % 64);
      if (had) return;
      i /= 64;
    }
  }

  void erase(std::size_t i) {
    for (auto& level : levels_) {
      std::uint64_t& word = level[i / 64];
      word &= ~(std::uint64_t{1} << (i % 64));
      if (word != 0) return;
      i /= 64;
    }
  }

  std::optional<std::size_t> next(std::size_t i) const {
    std::size_t level = 0;
    for (;; ++level) {
      if (level == levels_.size() || i / 64 >= levels_[level].size()) return std::nullopt;
      if (const std::uint64_t rest = levels_[level][i / 64] & (~std::uint64_t{0} << (i % 64))) {
        i = i / 64 * 64 + static_cast<std::size_t>(std::countr_zero(rest));
        break;
      }
      i = i / 64 + 1;
    }
    for (; level > 0; --level) i = i * 64 + static_cast<std::size_t>(std::countr_zero(levels_[level - 1][i]));
    return i;
  }

 private:
  std::vector<std::vector<std::uint64_t>> levels_;
};

class Partitioner {
 public:
  explicit Partitioner(const std::vector<std::vector<glm::dvec2>>& loops) {
    for (const auto& loop : loops) points_.insert(points_.end(), loop.begin(), loop.end());
    Index start = 0;
    std::vector<Index> hole_starts;
    std::vector<Index> hole_sizes;
    for (std::size_t i = 0; i < loops.size(); ++i) {
      const Index n = static_cast<Index>(loops[i].size());
      const Index first = static_cast<Index>(nodes_.size());
      for (Index k = 0; k < n; ++k) nodes_.push_back({start + k, first + (k + n - 1) % n, first + (k + 1) % n, false});
      if (i > 0 && n > 0) {
        hole_starts.push_back(first);
        hole_sizes.push_back(n);
      }
      start += n;
    }
    if (loops.empty() || loops[0].size() < 3) return;
    head_ = 0;
    size_ = static_cast<Index>(loops[0].size());
    if (!hole_starts.empty()) index_ring(static_cast<Index>(loops[0].size()));
    bridge_holes(hole_starts, hole_sizes);
  }

  std::vector<std::vector<Index>> run(PartitionWork* work) {
    if (head_ == kNone) return {};
    on_ring_twice_.assign(points_.size(), false);
    std::vector<bool> seen(points_.size(), false);
    Index node = head_;
    do {
      const Index v = nodes_[node].vertex;
      on_ring_twice_[v] = on_ring_twice_[v] || seen[v];
      seen[v] = true;
      node = nodes_[node].next;
    } while (node != head_);
    clip_ears();
    if (work) *work = work_;
    merge_pieces();
    std::vector<std::vector<Index>> out;
    for (auto& piece : pieces_)
      if (!piece.empty()) out.push_back(std::move(piece));
    return out;
  }

 private:
  const glm::dvec2& pos(Index node) const { return points_[nodes_[node].vertex]; }

  int turn_at(Index node) const { return turn(pos(nodes_[node].prev), pos(node), pos(nodes_[node].next)); }

  // Eberly's bridging: holes in order of decreasing rightmost x; from each
  // hole's rightmost vertex M, a ray to +x hits the current outer ring; the
  // bridge goes to the hit edge's far endpoint unless a reflex vertex inside
  // the triangle (M, hit, endpoint) blocks it, in which case to the blocking
  // vertex with the smallest angle to the ray.
  void bridge_holes(const std::vector<Index>& starts, const std::vector<Index>& sizes) {
    struct Hole {
      Index rightmost;
      glm::dvec2 at;  // its position
      std::size_t loop;
    };
    std::vector<Hole> holes;
    for (std::size_t h = 0; h < starts.size(); ++h) {
      Index best = starts[h];
      for (Index k = starts[h]; k < starts[h] + sizes[h]; ++k) {
        const glm::dvec2 p = pos(k), q = pos(best);
        if (p.x > q.x || (p.x == q.x && p.y < q.y)) best = k;
      }
      holes.push_back({best, pos(best), h});
    }
    std::sort(holes.begin(), holes.end(), [](const Hole& a, const Hole& b) {
      return a.at.x != b.at.x ? a.at.x > b.at.x : a.at.y < b.at.y;
    });
    for (const Hole& hole : holes) {
      const Index m = hole.rightmost;
      const std::optional<Index> found = indexed_bridge(m);
      const Index p = found ? *found : find_bridge(m);
      splice(p, m, sizes[hole.loop]);
      if (!in_ring_.empty()) {
        for (Index k = starts[hole.loop]; k < starts[hole.loop] + sizes[hole.loop]; ++k) in_ring_[k] = true;
        ++copies_[nodes_[p].vertex];
        ++copies_[nodes_[m].vertex];
        rays_.add(points_[nodes_[p].vertex], points_[nodes_[m].vertex], kBridge | static_cast<Index>(bridges_.size()));
        bridges_.push_back({nodes_[p].vertex, nodes_[m].vertex});
      }
    }
  }

  // The ring's edges and vertices indexed for indexed_bridge: every loop's
  // edges (those of holes not yet joined count once their hole joins), the
  // bridges as they are made, and every vertex.
  void index_ring(Index outer_size) {
    in_ring_.assign(points_.size(), false);
    std::fill(in_ring_.begin(), in_ring_.begin() + outer_size, true);
    copies_.assign(points_.size(), 1);
    loop_next_.resize(points_.size());
    std::vector<std::pair<glm::dvec2, std::uint32_t>> vertices(points_.size());
    for (Index k = 0; k < points_.size(); ++k) {
      loop_next_[k] = nodes_[k].next;
      rays_.add(points_[k], points_[loop_next_[k]], k);
      vertices[k] = {points_[k], k};
    }
    vertices_ = PointTree(std::move(vertices));
  }

  // find_bridge's answer found through the index, where it does not depend
  // on the order of the ring (which the index does not keep): the nearest
  // hit and the vertex that hides it are each one vertex, of one node (not
  // doubled by an earlier bridge). Otherwise nothing, and find_bridge walks
  // the ring. Each step is find_bridge's own, on the same numbers.
  std::optional<Index> indexed_bridge(Index m) {
    if (in_ring_.empty()) return std::nullopt;
    const glm::dvec2 mp = pos(m);
    double best_x = std::numeric_limits<double>::infinity();
    Index best = kNone;
    bool tied = false;
    glm::dvec2 hit{};
    rays_.along(mp, best_x, [&](Index id) {
      Index from, to;
      if (id & kBridge) {
        // A bridge runs both ways along the ring; only its upward way can be hit.
        const auto [p, q] = bridges_[id & ~kBridge];
        from = points_[p].y < points_[q].y ? p : q;
        to = from == p ? q : p;
      } else {
        if (!in_ring_[id]) return;
        from = id;
        to = loop_next_[id];
      }
      const glm::dvec2 a = points_[from], b = points_[to];
      const std::optional<double> exit = ray_exit(a, b, mp);
      if (!exit) return;
      const double x = *exit;
      const Index at = bridge_end(a, b, x, mp, from, to);
      if (x < best_x) {
        best_x = x;
        hit = {x, mp.y};
        best = at;
        tied = false;
      } else if (x == best_x && at != best) {
        tied = true;
      }
    });
    if (best == kNone || tied || copies_[best] != 1) return std::nullopt;
    const glm::dvec2 pp = points_[best];
    if (pp == hit) return best;

    const glm::dvec2 tri[3] = {mp, hit, pp};
    const bool ccw = orient2d(tri[0], tri[1], tri[2]) > 0;
    const glm::dvec2 lo = glm::min(glm::min(mp, hit), pp), hi = glm::max(glm::max(mp, hit), pp);
    Hiding nearest{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Index chosen = best;
    bool doubled = false;
    tied = false;
    vertices_.search(
        [&](const glm::dvec2& box_lo, const glm::dvec2& box_hi) {
          return box_hi.x < std::max(lo.x, mp.x) || box_lo.x > hi.x || box_hi.y < lo.y || box_lo.y > hi.y;
        },
        [&](Index v, const glm::dvec2& q) {
          if (!in_ring_[v] || q == pp || q.x < mp.x) return true;
          const std::optional<Hiding> h = hiding(tri, ccw, q);
          if (!h) return true;
          if (copies_[v] != 1) return !(doubled = true);
          if (turn_at(v) == 1) return true;
          if (*h < nearest) {
            nearest = *h;
            chosen = v;
            tied = false;
          } else if (*h == nearest) {
            tied = true;
          }
          return true;
        });
    if (doubled || tied) return std::nullopt;
    return chosen;
  }

  Index find_bridge(Index m) const {
    const glm::dvec2 mp = pos(m);
    double best_x = std::numeric_limits<double>::infinity();
    Index best = kNone;
    glm::dvec2 hit{};
    Index node = head_;
    do {
      const Index nx = nodes_[node].next;
      const glm::dvec2 a = pos(node), b = pos(nx);
      if (const std::optional<double> x = ray_exit(a, b, mp); x && *x < best_x) {
        best_x = *x;
        hit = {*x, mp.y};
        best = bridge_end(a, b, *x, mp, node, nx);
      }
      node = nx;
    } while (node != head_);
    if (best == kNone) throw std::invalid_argument("a hole is not inside the outer loop");
    if (pos(best) == hit) return pick_duplicate(best, mp);

    // Reflex vertices inside the triangle (M, hit, P) would hide P from M.
    const glm::dvec2 pp = pos(best);
    const glm::dvec2 tri[3] = {mp, hit, pp};
    const bool ccw = orient2d(tri[0], tri[1], tri[2]) > 0;
    Hiding nearest{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Index chosen = best;
    node = head_;
    do {
      const glm::dvec2 q = pos(node);
      if (node != best && q != pp && turn_at(node) != 1 && q.x >= mp.x) {
        if (const std::optional<Hiding> h = hiding(tri, ccw, q); h && *h < nearest) {
          nearest = *h;
          chosen = node;
        }
      }
      node = nodes_[node].next;
    } while (node != head_);
    return pick_duplicate(chosen, mp);
  }

  // Among the nodes at the same position as p (an earlier bridge doubled it),
  // the one whose interior wedge contains the direction to m.
  Index pick_duplicate(Index p, const glm::dvec2& m) const {
    if (in_wedge(p, m)) return p;
    const glm::dvec2 pp = pos(p);
    Index node = head_;
    do {
      if (node != p && pos(node) == pp && in_wedge(node, m)) return node;
      node = nodes_[node].next;
    } while (node != head_);
    return p;
  }

  bool in_wedge(Index node, const glm::dvec2& q) const {
    const glm::dvec2 a = pos(nodes_[node].prev), b = pos(node), c = pos(nodes_[node].next);
    if (orient2d(a, b, c) >= 0) return orient2d(b, c, q) >= 0 && orient2d(a, b, q) >= 0;
    return orient2d(b, c, q) >= 0 || orient2d(a, b, q) >= 0;
  }

  // p -> m -> (around the hole) -> m' -> p' -> old next of p.
  void splice(Index p, Index m, Index hole_size) {
    const Index p_next = nodes_[p].next;
    const Index m_prev = nodes_[m].prev;
    const Index m2 = static_cast<Index>(nodes_.size());
    nodes_.push_back({nodes_[m].vertex, m_prev, m2 + 1, false});
    nodes_.push_back({nodes_[p].vertex, m2, p_next, false});
    nodes_[m_prev].next = m2;
    nodes_[p_next].prev = m2 + 1;
    nodes_[p].next = m;
    nodes_[m].prev = p;
    size_ += hole_size + 2;
  }

  // What keeps v from being an ear: v itself where the ring does not turn
  // left there, else a vertex in the ear or on its new edge; kNone for an ear.
  Index ear_blocker(Index v) {
    ++work_.ears_asked;
    const Index p = nodes_[v].prev, n = nodes_[v].next;
    const glm::dvec2 a = pos(p), b = pos(v), c = pos(n);
    if (orient2d(a, b, c) <= 0 || turn(a, b, c) == 0) return v;
    // The box reaches as far as rounding puts a vertex off the new edge c -> a.
    const double margin = kStraightTurnSine * glm::distance(a, c) +
                          8.0 * std::numeric_limits<double>::epsilon() *
                              std::max({std::abs(a.x), std::abs(a.y), std::abs(c.x), std::abs(c.y)});
    const double lo_x = std::min({a.x, b.x, c.x}) - margin, hi_x = std::max({a.x, b.x, c.x}) + margin;
    const double lo_y = std::min({a.y, b.y, c.y}) - margin, hi_y = std::max({a.y, b.y, c.y}) + margin;
    // Parts of the plane outside the box, or wholly beyond a side of the ear by
    // more than the margin and what rounding can make of the test, hold no
    // vertex that could stop the ear: skipped.
    const double slack = 2.0 * margin + 32.0 * std::numeric_limits<double>::epsilon() *
                                            std::max({std::abs(a.x), std::abs(a.y), std::abs(b.x), std::abs(b.y),
                                                      std::abs(c.x), std::abs(c.y)});
    const auto beyond = [&](const glm::dvec2& u, const glm::dvec2& w, const glm::dvec2& lo, const glm::dvec2& hi) {
      const glm::dvec2 d = w - u;
      const double length = glm::length(d);
      for (const glm::dvec2 k : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)}) {
        const double reach = length * (slack + 8.0 * std::numeric_limits<double>::epsilon() *
                                                   (std::abs(k.x - u.x) + std::abs(k.y - u.y)));
        if (d.x * (k.y - u.y) - d.y * (k.x - u.x) >= -reach) return false;
      }
      return true;
    };
    const auto skip = [&](const glm::dvec2& lo, const glm::dvec2& hi) {
      return hi.x < lo_x || lo.x > hi_x || hi.y < lo_y || lo.y > hi_y || beyond(a, b, lo, hi) || beyond(b, c, lo, hi) ||
             beyond(c, a, lo, hi);
    };
    // Only a vertex that is not strictly convex can lie inside an ear.
    Index blocker = kNone;
    reflex_.search(skip, [&](Index q, const glm::dvec2& s) {
      ++work_.vertices_examined;
      if (s.x < lo_x || s.x > hi_x || s.y < lo_y || s.y > hi_y) return true;
      if (nodes_[q].removed || q == p || q == v || q == n || s == a || s == b || s == c) return true;
      // The ear's one new edge, c -> a, must not pass through the ring either.
      const bool inside = orient2d(a, b, s) >= 0 && orient2d(b, c, s) >= 0 && orient2d(c, a, s) >= 0;
      if (inside || between_up_to_rounding(c, s, a)) blocker = q;
      return blocker == kNone;
    });
    return blocker;
  }

  bool ring_is_convex() const {
    Index node = head_;
    do {
      if (!convex_turn(turn_at(node))) return false;
      node = nodes_[node].next;
    } while (node != head_);
    return true;
  }

  void remove(Index v) {
    const Index p = nodes_[v].prev, n = nodes_[v].next;
    nodes_[p].next = n;
    nodes_[n].prev = p;
    nodes_[v].removed = true;
    if (head_ == v) head_ = n;
    --size_;
    unsettled_.erase(place_[v]);
    unsettled_.insert(place_[p]);
    unsettled_.insert(place_[n]);
    for (Index e = stopped_first_[v]; e != kNone; e = stopped_[e].second) {
      const Index u = stopped_[e].first;
      if (blocker_[u] == v && !nodes_[u].removed) unsettled_.insert(place_[u]);
    }
  }

  // v is no ear for as long as its neighbours and blocker stay.
  void settle(Index v, Index blocker) {
    unsettled_.erase(place_[v]);
    blocker_[v] = blocker;
    if (blocker == v) return;
    stopped_.emplace_back(v, stopped_first_[blocker]);
    stopped_first_[blocker] = static_cast<Index>(stopped_.size() - 1);
  }

  // The first node after v round the ring that may have become an ear since
  // it was last asked, and how many steps round that is (kNone, none).
  std::pair<Index, Index> next_unsettled(Index v) const {
    std::optional<std::size_t> at = unsettled_.next(place_[v] + 1);
    if (!at) at = unsettled_.next(0);
    if (!at) return {kNone, kNone};
    return {at_place_[*at], steps(v, at_place_[*at])};
  }

  // Steps round the ring from u on to w, a whole lap if w is u.
  Index steps(Index u, Index w) const {
    const auto n = static_cast<Index>(at_place_.size());
    return (place_[w] + n - place_[u] - 1) % n + 1;
  }

  void emit_ring() {
    std::vector<Index> piece;
    Index node = head_;
    do {
      piece.push_back(nodes_[node].vertex);
      node = nodes_[node].next;
    } while (node != head_);
    pieces_.push_back(std::move(piece));
  }

  // Ear clipping that leaves straight vertices alone and stops as soon as
  // what remains is convex. Clipping an ear only shrinks its neighbours'
  // angles, so the vertices that are not strictly convex at the start are
  // the only ones an ear can ever contain.
  //
  // The walk round the ring passes over the nodes whose answer cannot have
  // changed since they were last asked: neither neighbour nor what blocked
  // the ear has gone. They would answer no again, and asking every node on
  // every lap made the laps O(n^1.5) on a square with k x k holes (a row of
  // holes is clipped a few ears a lap).
  void clip_ears() {
    std::vector<std::pair<glm::dvec2, Index>> reflex;
    place_.assign(nodes_.size(), kNone);
    Index node = head_;
    do {
      place_[node] = static_cast<Index>(at_place_.size());
      at_place_.push_back(node);
      if (turn_at(node) != 1) reflex.emplace_back(pos(node), node);
      node = nodes_[node].next;
    } while (node != head_);
    reflex_ = PointTree(std::move(reflex));
    unsettled_ = Places(at_place_.size());
    for (std::size_t k = 0; k < at_place_.size(); ++k) unsettled_.insert(k);
    blocker_.assign(nodes_.size(), kNone);
    stopped_first_.assign(nodes_.size(), kNone);
    Index stop = node;  // a full lap back here without progress ends the lap
    while (size_ > 3) {
      // Nodes at the same input vertex next to each other (the two ends of a
      // bridge, once everything between them is clipped) collapse into one.
      if (nodes_[nodes_[node].next].vertex == nodes_[node].vertex) {
        const Index n = nodes_[node].next;
        if (stop == n) stop = node;
        remove(n);
        continue;
      }
      const Index blocker = ear_blocker(node);
      if (blocker == kNone) {
        pieces_.push_back({nodes_[nodes_[node].prev].vertex, nodes_[node].vertex, nodes_[nodes_[node].next].vertex});
        const Index next = nodes_[node].next;
        remove(node);
        node = stop = next;
        continue;
      }
      settle(node, blocker);
      if (const auto [ahead, distance] = next_unsettled(node); ahead != kNone && distance < steps(node, stop)) {
        node = ahead;
        continue;
      }
      node = stop;
      if (ring_is_convex()) break;
      // No ear on a whole lap: the input is not a simple polygon (or is one
      // only up to rounding). Clip any strictly convex vertex to make progress.
      Index forced = kNone;
      Index q = head_;
      do {
        if (turn_at(q) == 1) forced = q;
        q = nodes_[q].next;
      } while (q != head_ && forced == kNone);
      if (forced == kNone) break;
      pieces_.push_back(
          {nodes_[nodes_[forced].prev].vertex, nodes_[forced].vertex, nodes_[nodes_[forced].next].vertex});
      node = stop = nodes_[forced].next;
      remove(forced);
    }
    emit_ring();
  }

  // Hertel-Mehlhorn: drop every diagonal whose removal keeps both of its
  // pieces' union convex, longest diagonals first. The pieces are rings of
  // slots (a vertex's place in a piece) spliced together at each merge, so a
  // merge costs its two turns and its pieces' shared bridge ends, not their
  // lengths: a comb's spine takes in thousands of teeth, and copying it for
  // each (and searching it for the diagonal) made merging quadratic.
  void merge_pieces() {
    Rings rings(pieces_);
    for (std::size_t i = 0; i < pieces_.size(); ++i)
      for (const Index v : pieces_[i])
        if (on_ring_twice_[v]) rings.twice[i].insert(v);
    struct Diagonal {
      Index a, b;
      double length2;
    };
    std::vector<Diagonal> diagonals;
    for (const auto& [edge, slot] : rings.edge_slot) {
      const auto a = static_cast<Index>(edge >> 32), b = static_cast<Index>(edge);
      if (a < b && rings.slot_of(b, a)) {
        const glm::dvec2 d = points_[b] - points_[a];
        diagonals.push_back({a, b, glm::dot(d, d)});
      }
    }
    std::stable_sort(diagonals.begin(), diagonals.end(),
                     [](const Diagonal& x, const Diagonal& y) { return x.length2 > y.length2; });
    for (const Diagonal& d : diagonals) try_merge(rings, *rings.slot_of(d.a, d.b), *rings.slot_of(d.b, d.a));
    for (std::size_t i = 0; i < pieces_.size(); ++i) pieces_[i] = rings.piece(i);
  }

  // The pieces as rings of slots, merged into one another.
  struct Rings {
    struct Slot {
      Index vertex, prev, next;
      Index piece;  // the piece it was made in (find() gives the one holding it now)
    };
    explicit Rings(const std::vector<std::vector<Index>>& pieces)
        : head(pieces.size()), owner(pieces.size()), twice(pieces.size()) {
      std::iota(owner.begin(), owner.end(), Index{0});
      for (std::size_t i = 0; i < pieces.size(); ++i) {
        const auto first = static_cast<Index>(slots.size()), n = static_cast<Index>(pieces[i].size());
        head[i] = first;
        for (Index k = 0; k < n; ++k) {
          slots.push_back({pieces[i][k], first + (k + n - 1) % n, first + (k + 1) % n, static_cast<Index>(i)});
          edge_slot.emplace_back(edge(pieces[i][k], pieces[i][(k + 1) % n]), first + k);
        }
      }
      // An edge listed twice (a ring that runs along itself) keeps its last
      // slot, the highest: sorted, the last of each edge's run.
      std::sort(edge_slot.begin(), edge_slot.end());
      const auto same_edge = [](const auto& x, const auto& y) { return x.first == y.first; };
      edge_slot.erase(edge_slot.begin(), std::unique(edge_slot.rbegin(), edge_slot.rend(), same_edge).base());
    }
    static std::uint64_t edge(Index a, Index b) { return std::uint64_t{a} << 32 | b; }
    // The slot edge a -> b starts from, or null.
    Index* slot_of(Index a, Index b) {
      const auto it = std::lower_bound(edge_slot.begin(), edge_slot.end(), edge(a, b),
                                       [](const auto& e, std::uint64_t key) { return e.first < key; });
      return it != edge_slot.end() && it->first == edge(a, b) ? &it->second : nullptr;
    }
    Index find(Index p) {
      while (owner[p] != p) p = owner[p] = owner[owner[p]];
      return p;
    }
    // A piece's vertices from its head round (none once merged into another).
    std::vector<Index> piece(std::size_t i) const {
      std::vector<Index> out;
      if (head[i] == kNone) return out;
      Index s = head[i];
      do {
        out.push_back(slots[s].vertex);
        s = slots[s].next;
      } while (s != head[i]);
      return out;
    }

    std::vector<Slot> slots;
    std::vector<Index> head;   // per piece: its first slot, kNone once merged into another
    std::vector<Index> owner;  // union-find over pieces
    std::vector<std::set<Index>> twice;  // per piece: its vertices the ring passes twice (bridge ends)
    // Each directed edge (a << 32 | b) and the slot it starts from, by edge: a
    // tree map of them was a third of partitioning the 1M square with holes.
    std::vector<std::pair<std::uint64_t, Index>> edge_slot;
  };

  // The piece holding a -> b (from slot sa) and the one holding b -> a (from
  // tb) become one, if the union is convex and passes no vertex twice: it
  // then runs from b round the first piece to a, then through the second's
  // vertices between a and b.
  void try_merge(Rings& r, Index sa, Index tb) const {
    const Index pa = r.find(r.slots[sa].piece), pb = r.find(r.slots[tb].piece);
    if (pa == pb) return;
    auto& s = r.slots;
    const Index sb = s[sa].next, ta = s[tb].next;
    const Index a = s[sa].vertex, b = s[tb].vertex;
    if (s[sb].vertex != b || s[ta].vertex != a) return;
    // The union turns at a from the first piece's vertex before it to the
    // second's after it, and at b from the second's before it to the first's after.
    if (!convex_turn(turn(points_[s[s[sa].prev].vertex], points_[a], points_[s[s[ta].next].vertex])) ||
        !convex_turn(turn(points_[s[s[tb].prev].vertex], points_[b], points_[s[s[sb].next].vertex])))
      return;
    // Only a vertex the ring passes twice (a bridge's end) can repeat.
    std::set<Index>& big = r.twice[pa].size() >= r.twice[pb].size() ? r.twice[pa] : r.twice[pb];
    std::set<Index>& small = &big == &r.twice[pa] ? r.twice[pb] : r.twice[pa];
    for (const Index v : small)
      if (v != a && v != b && big.count(v)) return;
    big.insert(small.begin(), small.end());
    if (&big != &r.twice[pa]) std::swap(r.twice[pa], r.twice[pb]);
    r.twice[pb].clear();
    // The second piece's slots of a and b go; the edge leaving a there now
    // leaves from the first piece's.
    const Index after_a = s[ta].next, before_b = s[tb].prev;
    s[sa].next = after_a;
    s[after_a].prev = sa;
    s[before_b].next = sb;
    s[sb].prev = before_b;
    if (Index* slot = r.slot_of(a, s[after_a].vertex); slot && *slot == ta) *slot = sa;
    r.head[pa] = sb;
    r.head[pb] = kNone;
    r.owner[pb] = pa;
  }

  std::vector<glm::dvec2> points_;
  std::vector<Node> nodes_;
  Index head_ = kNone;
  Index size_ = 0;
  // indexed_bridge's, by vertex (a vertex's first node has its number): on
  // the ring yet, how many nodes it has, the next vertex of its loop.
  static constexpr Index kBridge = Index{1} << 31;  // a bridge's id in rays_
  std::vector<bool> in_ring_;
  std::vector<Index> copies_, loop_next_;
  std::vector<std::pair<Index, Index>> bridges_;
  HorizontalRays rays_;
  PointTree vertices_;
  std::vector<std::vector<Index>> pieces_;
  PointTree reflex_;  // nodes not strictly convex when clipping began
  // clip_ears' walk. A node's place round the ring when clipping began (the
  // ring only loses nodes after that, so the places keep its order), and the
  // node at each place; the places whose nodes may have become ears since
  // last asked; what stopped each node asked being an ear, and under each
  // blocker the nodes it stopped (a list through stopped_: node, next entry).
  std::vector<Index> place_, at_place_;
  Places unsettled_;
  std::vector<Index> blocker_, stopped_first_;
  std::vector<std::pair<Index, Index>> stopped_;
  PartitionWork work_;
  std::vector<bool> on_ring_twice_;  // input vertices the ring passes more than once
};

}  // namespace

std::vector<std::vector<std::uint32_t>> convex_partition(const std::vector<std::vector<glm::dvec2>>& loops,
                                                         PartitionWork* work) {
  // Most faces (a wall's tiles, a hip roof's) turn left at every corner: one
  // piece, listed as clipping the ear at vertex 0 first and merging lists it
  // (a triangle as it is, a larger loop from its last vertex), so that every
  // triangulation made from the pieces stays what it was.
  if (loops.size() == 1 && every_turn(loops[0], [](int t) { return t == 1; })) {
    const auto n = static_cast<Index>(loops[0].size());
    std::vector<Index> piece(n);
    std::iota(piece.begin(), piece.end(), Index{0});
    if (n > 3) std::rotate(piece.begin(), piece.end() - 1, piece.end());
    return {piece};
  }
  return Partitioner(loops).run(work);
}

bool is_convex(const std::vector<glm::dvec2>& loop) { return every_turn(loop, convex_turn); }

}  // namespace procex
