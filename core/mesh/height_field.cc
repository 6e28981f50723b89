#include "core/mesh/height_field.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/nesting.h"
#include "core/geom/predicates.h"
#include "core/geom/segment_intersections.h"

namespace procex {

namespace {

struct Directed {
  std::uint32_t from, to;
  bool operator<(const Directed& o) const { return from != o.from ? from < o.from : to < o.to; }
};

// An edge between two vertices, the lower id first, and which way it runs:
// +1 from the lower, -1 to it.
struct Way {
  std::uint32_t lo, hi;
  int way;
  bool operator<(const Way& o) const { return lo != o.lo ? lo < o.lo : hi < o.hi; }
};

Way way_of(std::uint32_t from, std::uint32_t to) { return from < to ? Way{from, to, 1} : Way{to, from, -1}; }

// The edges of `ways` not matched by one running the other way: the boundary
// of the triangles they came from, sorted by where they start.
std::vector<Directed> unmatched(std::vector<Way>& ways) {
  std::sort(ways.begin(), ways.end());
  std::vector<Directed> out;
  for (std::size_t first = 0; first < ways.size();) {
    int surplus = 0;
    std::size_t last = first;
    for (; last < ways.size() && ways[last].lo == ways[first].lo && ways[last].hi == ways[first].hi; ++last)
      surplus += ways[last].way;
    for (; surplus > 0; --surplus) out.push_back({ways[first].lo, ways[first].hi});
    for (; surplus < 0; ++surplus) out.push_back({ways[first].hi, ways[first].lo});
    first = last;
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Points in the plan by x, then y.
bool lesser(glm::dvec2 a, glm::dvec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; }

// A segment of the plan, its lesser end first, and their order.
using Segment = std::pair<glm::dvec2, glm::dvec2>;
Segment plan_segment(glm::dvec2 a, glm::dvec2 b) { return lesser(b, a) ? Segment(b, a) : Segment(a, b); }
bool segment_less(const Segment& e, const Segment& f) {
  return lesser(e.first, f.first) || (e.first == f.first && lesser(e.second, f.second));
}

// Which way a simple loop turns, exactly: at its least vertex (by x, then y)
// the loop is convex, and its neighbours there are not on one line with it.
int turn_of_simple_loop(const std::vector<glm::dvec2>& loop) {
  const std::size_t n = loop.size();
  const auto least = static_cast<std::size_t>(std::min_element(loop.begin(), loop.end(), lesser) - loop.begin());
  return orient2d(loop[(least + n - 1) % n], loop[least], loop[(least + 1) % n]);
}

// Whether a sliver above the base turns clockwise seen from above, folding
// its face back, by more than `most` (and its coordinates' rounding): the
// triangles beside it then cover the fold's shadow twice. The shadow is
// thinner than the search's tolerance, but two triangles overlapping along
// a long thin strip can still cross by more than it (a ridge vertex moved
// 2e-5 m across a ridge, tolerance 1e-5: HeightField's moved vertices).
// Slivers that turn either way by their rounding (three points of a straight
// ridge) or by the sweep's clustering (a spiky roof's, up to 0.0015 of the
// tolerance at 262,144 corners) move nothing the search would see.
bool folded_past(const MeshTriangle& t, double most) {
  const glm::dvec2 a(t.p[0]), b(t.p[1]), c(t.p[2]);
  const double twice_area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  if (!(twice_area < 0.0)) return false;
  const double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  double magnitude = longest;
  for (const glm::dvec3& p : t.p) magnitude = std::max({magnitude, std::abs(p.x), std::abs(p.y)});
  return -twice_area / longest > std::max(most, 64.0 * std::numeric_limits<double>::epsilon() * magnitude);
}

}  // namespace

std::optional<std::vector<std::uint32_t>> proven_apart_over_base(const std::vector<MeshTriangle>& triangles,
                                                                 std::size_t slivers, double tolerance) {
  if (triangles.empty()) return std::nullopt;
  double lowest = std::numeric_limits<double>::infinity();
  for (const MeshTriangle& t : triangles)
    for (const glm::dvec3& p : t.p) lowest = std::min(lowest, p.z);

  std::vector<Way> all, base;
  all.reserve(3 * triangles.size());
  std::vector<glm::dvec2> position;  // by welded id, of the base's vertices
  const std::size_t solid = triangles.size() - slivers;
  std::vector<std::uint32_t> left(solid, kCovered);
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const MeshTriangle& t = triangles[i];
    // An edge between one welded vertex and itself is a point: no boundary.
    for (int k = 0; k < 3; ++k)
      if (t.v[k] != t.v[(k + 1) % 3]) all.push_back(way_of(t.v[k], t.v[(k + 1) % 3]));
    const bool flat = t.p[0].z == lowest && t.p[1].z == lowest && t.p[2].z == lowest;
    if (i < solid) {
      const int turn = orient2d(glm::dvec2(t.p[0]), glm::dvec2(t.p[1]), glm::dvec2(t.p[2]));
      if (turn == 0) left[i] = kUpright;  // covers nothing seen from above, so it may be passed through
      if (turn < 0 && !flat) return std::nullopt;  // facing down above the base: a second sheet may be there
      if (turn >= 0) continue;
    } else if (!flat) {
      if (folded_past(t, 0.01 * tolerance)) return std::nullopt;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      if (t.v[k] != t.v[(k + 1) % 3]) base.push_back(way_of(t.v[k], t.v[(k + 1) % 3]));
      if (position.size() <= t.v[k]) position.resize(t.v[k] + 1);
      position[t.v[k]] = glm::dvec2(t.p[k]);
    }
  }
  if (base.empty()) return std::nullopt;
  if (!unmatched(all).empty()) return std::nullopt;  // not closed, as triangles

  // The base's outline, as loops: each vertex on it left by one edge of it.
  const std::vector<Directed> outline = unmatched(base);
  for (std::size_t k = 1; k < outline.size(); ++k)
    if (outline[k].from == outline[k - 1].from) return std::nullopt;  // the outline touches itself there
  std::vector<std::vector<glm::dvec2>> loops;
  std::vector<char> used(outline.size(), 0);
  for (std::size_t start = 0; start < outline.size(); ++start) {
    if (used[start]) continue;
    std::vector<glm::dvec2> loop;
    for (std::size_t k = start; !used[k];) {
      used[k] = 1;
      loop.push_back(position[outline[k].from]);
      const auto next = std::lower_bound(outline.begin(), outline.end(), Directed{outline[k].to, 0});
      if (next == outline.end() || next->from != outline[k].to) return std::nullopt;
      k = static_cast<std::size_t>(next - outline.begin());
      if (k != start && used[k]) return std::nullopt;
    }
    if (loop.size() < 3) return std::nullopt;
    loops.push_back(std::move(loop));
  }
  const LoopSegments segments = loop_segments(loops);
  if (!intersecting_segment_pairs(segments.segments, segments.next, 1).empty()) return std::nullopt;
  const LoopNesting nesting = loop_nesting(loops);
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (turn_of_simple_loop(loops[i]) != (nesting.depth[i] % 2 == 0 ? -1 : 1)) return std::nullopt;
  if (std::find(left.begin(), left.end(), kUpright) == left.end()) return left;

  // Upright triangles standing on an edge of the outline, their shadow that
  // edge (height_field.h), by the edge; but not on edges that another edge,
  // not meeting them, comes nearer than the tolerance: the search takes
  // walls on those as touching.
  std::vector<Segment> edges;  // the outline's, in the plan
  edges.reserve(outline.size());
  for (const Directed& d : outline) edges.push_back(plan_segment(position[d.from], position[d.to]));
  std::sort(edges.begin(), edges.end(), segment_less);
  std::vector<char> near_edge(edges.size(), 0);  // by place in `edges`
  // The loops' segments are the outline's edges, made from the same
  // positions. One not among them (none is known) is no wall's shadow either,
  // which is looked up the same way below: nothing to mark.
  const auto mark_near = [&](const Segment2& s) {
    const Segment e = plan_segment(s.a, s.b);
    const auto at = std::lower_bound(edges.begin(), edges.end(), e, segment_less);
    if (at != edges.end() && *at == e) near_edge[static_cast<std::size_t>(at - edges.begin())] = 1;
  };
  for_each_near_segment_pair(segments.segments, tolerance, [&](std::size_t i, std::size_t j) {
    const Segment2 &si = segments.segments[i], &sj = segments.segments[j];
    if (segments.next[i] != j && segments.next[j] != i && segments_meet(si, sj, tolerance)) {
      mark_near(si);
      mark_near(sj);
    }
    return true;
  });
  for (std::size_t i = 0; i < solid; ++i) {
    if (left[i] != kUpright) continue;
    const MeshTriangle& t = triangles[i];
    const glm::dvec2 a(t.p[0]), b(t.p[1]), c(t.p[2]);
    // Its shadow's two ends: a wall split along a diagonal has each twice.
    const glm::dvec2 w = a == b ? c : b;
    if (w == a || (a != b && c != a && c != b)) continue;  // its shadow's ends are not two of its corners
    const Segment shadow = plan_segment(a, w);
    const auto at = std::lower_bound(edges.begin(), edges.end(), shadow, segment_less);
    if (at != edges.end() && *at == shadow && !near_edge[static_cast<std::size_t>(at - edges.begin())])
      left[i] = static_cast<std::uint32_t>(at - edges.begin());
  }
  return left;
}

}  // namespace procex
