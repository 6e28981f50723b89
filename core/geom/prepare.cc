#include "core/geom/prepare.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/geom/nesting.h"
#include "core/geom/segment_intersections.h"
#include "core/geom/tolerances.h"

namespace procex {

namespace {

// Footprints are metres in a projected CRS, whose coordinates stay within
// about 2e7 m; beyond this a coordinate is a mistake (degrees scaled wrong, a
// corrupt file), and at 1e308 the bounding box overflows and every tolerance
// with it.
constexpr double kMaxCoordinate = 1e10;

std::string fmt(double v) {
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

std::string fmt(const glm::dvec2& p) { return "(" + fmt(p.x) + ", " + fmt(p.y) + ")"; }

std::string where(std::size_t loop, std::size_t vertex) {
  return "loop " + std::to_string(loop) + " vertex " + std::to_string(vertex);
}

void check_values(const Footprint& fp) {
  if (fp.loops.empty()) throw InputError("the footprint has no loops");
  for (std::size_t li = 0; li < fp.loops.size(); ++li) {
    const Loop& loop = fp.loops[li];
    const int l = static_cast<int>(li);
    if (loop.points.size() != loop.edges.size())
      throw InputError("loop " + std::to_string(li) + " has " + std::to_string(loop.points.size()) + " points but " +
                           std::to_string(loop.edges.size()) + " edges",
                       l);
    for (std::size_t k = 0; k < loop.points.size(); ++k) {
      const glm::dvec2& p = loop.points[k];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        throw InputError(where(li, k) + " has a coordinate that is not a finite number " + fmt(p), l, static_cast<int>(k));
      if (std::max(std::abs(p.x), std::abs(p.y)) > kMaxCoordinate)
        throw InputError(where(li, k) + " at " + fmt(p) + " lies farther than " + fmt(kMaxCoordinate) +
                             " m from the origin: footprints are read as metres in a projected CRS; reproject the "
                             "file or fix the coordinate",
                         l, static_cast<int>(k));
      const double a = loop.edges[k].angle_deg;
      if (!(a >= -90.0 && a <= 90.0))
        throw InputError("loop " + std::to_string(li) + " edge " + std::to_string(k) + " (id " +
                             std::to_string(loop.edges[k].id) + ", from vertex " + std::to_string(k) + ") has angle " +
                             fmt(a) + ", outside [-90, 90] degrees",
                         l, static_cast<int>(k));
    }
  }
}

// Merges runs of consecutive vertices closer than merge: the edge between two
// merged vertices has no length, so it is dropped and the first vertex keeps
// the outgoing edge of the last.
// original receives the input index of each kept vertex.
Loop merge_close_vertices(const Loop& loop, std::size_t li, double merge, std::vector<std::string>& notes,
                          std::vector<std::size_t>& original) {
  Loop out;
  for (std::size_t k = 0; k < loop.points.size(); ++k) {
    if (!out.points.empty()) {
      const double d = glm::distance(loop.points[k], out.points.back());
      if (d <= merge) {
        notes.push_back(where(li, k) + " is " + fmt(d) + " from vertex " + std::to_string(original.back()) +
                        ": merged into it, dropping edge id " + std::to_string(out.edges.back().id));
        out.edges.back() = loop.edges[k];
        continue;
      }
    }
    out.points.push_back(loop.points[k]);
    out.edges.push_back(loop.edges[k]);
    original.push_back(k);
  }
  while (out.points.size() > 1 && glm::distance(out.points.back(), out.points.front()) <= merge) {
    notes.push_back(where(li, original.back()) + " is " + fmt(glm::distance(out.points.back(), out.points.front())) +
                    " from vertex " + std::to_string(original.front()) + ": merged into it, dropping edge id " +
                    std::to_string(out.edges.back().id));
    out.points.pop_back();
    out.edges.pop_back();
    original.pop_back();
  }
  return out;
}

// Edges that meet, or that are apart only by the rounding of their
// coordinates (`within`): a loop whose sides are no further apart than that
// has no width there for the sweep to resolve. (Farther apart, a near touch is
// a shape: tests/data/synthetic's e_near_touch cases, 7e-10 of their size.)
void check_crossings(const Footprint& fp, const std::vector<std::vector<std::size_t>>& original, double within) {
  std::vector<std::vector<glm::dvec2>> loops;
  for (const Loop& loop : fp.loops) loops.push_back(loop.points);
  const LoopSegments segs = loop_segments(loops);
  const auto pairs = intersecting_segment_pairs(segs.segments, segs.next, 1, within);
  if (pairs.empty()) return;
  auto locate = [&](std::size_t s) {
    const std::size_t li = static_cast<std::size_t>(std::upper_bound(segs.first.begin(), segs.first.end(), s) -
                                                    segs.first.begin()) - 1;
    return std::pair{li, s - segs.first[li]};
  };
  const auto [la, ea] = locate(pairs[0].first);
  const auto [lb, eb] = locate(pairs[0].second);
  auto edge_text = [&](std::size_t li, std::size_t e) {
    const Loop& loop = fp.loops[li];
    const std::size_t n = loop.points.size();
    return "edge " + std::to_string(original[li][e]) + " " + fmt(loop.points[e]) + "-" + fmt(loop.points[(e + 1) % n]);
  };
  if (la == lb)
    throw InputError("loop " + std::to_string(la) + " intersects itself: its " + edge_text(la, ea) + " and " +
                         edge_text(lb, eb) + " meet",
                     static_cast<int>(la), static_cast<int>(original[la][ea]));
  throw InputError("loops " + std::to_string(la) + " and " + std::to_string(lb) + " cross or touch: " +
                       edge_text(la, ea) + " of loop " + std::to_string(la) + " meets " + edge_text(lb, eb) +
                       " of loop " + std::to_string(lb),
                   static_cast<int>(la), static_cast<int>(original[la][ea]));
}

// Reverses the loop's direction; edge k ran from point k to k + 1 and keeps
// its spec, so after reversal it is edge n - 2 - k.
void reverse_loop(Loop& loop) {
  const std::size_t n = loop.points.size();
  std::reverse(loop.points.begin(), loop.points.end());
  std::vector<EdgeSpec> edges(n);
  for (std::size_t i = 0; i < n; ++i) edges[i] = loop.edges[(2 * n - 2 - i) % n];
  loop.edges = std::move(edges);
}

}  // namespace

PreparedFootprint prepare_footprint(const Footprint& footprint) {
  check_values(footprint);
  PreparedFootprint out;
  out.footprint.profiles = footprint.profiles;  // the kept edges still name them
  const double merge = merge_distance(footprint);
  const double scale = length_scale(footprint);
  std::vector<std::vector<std::size_t>> original;  // input vertex index of each kept vertex
  for (std::size_t li = 0; li < footprint.loops.size(); ++li) {
    const Loop& in = footprint.loops[li];
    std::vector<std::size_t> kept;
    Loop loop = merge_close_vertices(in, li, merge, out.notes, kept);
    if (loop.points.size() < 3)
      throw InputError("loop " + std::to_string(li) + " has " + std::to_string(loop.points.size()) +
                           " distinct vertices (points closer than " + fmt(merge) +
                           " m count as one), fewer than 3: it encloses nothing to build on; fix or remove it",
                       static_cast<int>(li), 0);
    out.footprint.loops.push_back(std::move(loop));
    original.push_back(std::move(kept));
  }
  check_crossings(out.footprint, original, rounding_distance(out.footprint));
  // Only now: a bow-tie also has no area, but is better called self-intersecting.
  for (std::size_t li = 0; li < out.footprint.loops.size(); ++li)
    if (std::abs(0.5 * twice_signed_area(out.footprint.loops[li].points)) <= kLoopAreaRelative * scale * scale)
      throw InputError("loop " + std::to_string(li) + " has no area", static_cast<int>(li), 0);

  std::vector<std::vector<glm::dvec2>> loops;
  for (const Loop& loop : out.footprint.loops) loops.push_back(loop.points);
  const LoopNesting nesting = loop_nesting(loops);
  for (std::size_t li = 0; li < loops.size(); ++li) {
    const bool ccw = twice_signed_area(loops[li]) > 0.0;
    const bool want_ccw = nesting.depth[li] % 2 == 0;
    if (ccw == want_ccw) continue;
    reverse_loop(out.footprint.loops[li]);
    out.notes.push_back("loop " + std::to_string(li) + " ran " + (ccw ? "counter-clockwise" : "clockwise") +
                        " but lies at nesting depth " + std::to_string(nesting.depth[li]) + " (" +
                        (want_ccw ? "material" : "a hole") + "): reversed");
  }
  return out;
}

}  // namespace procex
