#include "core/sweep/surface_output.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <span>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/geom/polygon3.h"
#include "core/geom/round_edge.h"
#include "core/geom/segment_distance.h"
#include "core/geom/turn.h"
#include "core/sweep/spares.h"

namespace procex::engine {
namespace {

struct FaceFrame {
  glm::dvec3 u, w;  // in-plane axes; (u, w, outward) is right-handed
  glm::dvec2 to2d(glm::dvec3 p) const { return {glm::dot(p, u), glm::dot(p, w)}; }
};

FaceFrame frame_of(glm::dvec3 n) {
  const glm::dvec3 helper = std::abs(n.z) < 0.9 ? glm::dvec3{0, 0, 1} : glm::dvec3{1, 0, 0};
  const glm::dvec3 u = glm::normalize(glm::cross(helper, n));
  return {u, glm::cross(n, u)};
}

FaceFrame frame_of(const FaceGroup& f) { return frame_of(f.outward); }

double signed_area(std::span<const glm::dvec2> pts) {
  double a = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) a += cross(pts[i], pts[(i + 1) % pts.size()]);
  return 0.5 * a;
}

bool inside(std::span<const glm::dvec2> poly, glm::dvec2 q) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y > q.y) != (poly[j].y > q.y) &&
        q.x < (poly[j].x - poly[i].x) * (q.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
      in = !in;
  }
  return in;
}

[[noreturn]] void open_face(const FaceGroup& f, std::uint32_t v, const glm::dvec3& p, const PlanPosition& at) {
  std::ostringstream msg;
  msg << "sweep: the boundary of " << (f.kind == FaceKind::Side ? "the face of edge " : "a horizontal face ")
      << (f.kind == FaceKind::Side ? std::to_string(f.source_edge) : std::string())
      << " does not close at vertex " << v << " " << at(p);
  throw SweepError(msg.str(), p.z, {f.source_edge});
}

// A chained loop that passes a vertex twice (two parts of a face touching
// there, the sharpest turn leading into the other part) is two loops.
void split_at_repeats(std::vector<std::uint32_t> loop, std::vector<std::vector<std::uint32_t>>& out) {
  std::map<std::uint32_t, std::size_t> seen;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto [it, fresh] = seen.try_emplace(loop[i], i);
    if (fresh) continue;
    const auto first = loop.begin() + static_cast<std::ptrdiff_t>(it->second);
    const auto again = loop.begin() + static_cast<std::ptrdiff_t>(i);
    split_at_repeats({first, again}, out);
    loop.erase(first, again);
    return split_at_repeats(std::move(loop), out);
  }
  out.push_back(std::move(loop));
}

bool half_edge_less(const HalfEdge& a, const HalfEdge& b) { return a.from != b.from ? a.from < b.from : a.to < b.to; }
bool half_edge_equal(const HalfEdge& a, const HalfEdge& b) { return a.from == b.from && a.to == b.to; }

// Buffers reused from face to face (most faces have a handful of half-edges),
// and from one surface of the thread to the next (spares.h).
struct ChainScratch {
  // The last surface's loops are not this one's.
  void next_surface(std::size_t vertices) {
    seen.assign(vertices, 0);
    loop_id = 0;
  }

  std::vector<HalfEdge> given, hs;
  std::vector<std::pair<double, std::uint32_t>> corners, inside;  // (position, vertex)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links;     // (vertex, a neighbour in the face)
  std::vector<char> used;
  std::vector<std::uint32_t> seen;  // vertex -> the last loop (or a face's outer loops) that passed it
  std::uint32_t loop_id = 0;
  std::vector<std::uint32_t> loop;
  std::vector<std::vector<std::uint32_t>> loops;  // what chain_loops made
  std::vector<glm::dvec2> pts;                    // the outer loops' points in the face's frame
  std::vector<std::size_t> outer_from;            // outer loop i: its points from here in pts
  std::vector<double> outer_area;
  std::vector<std::size_t> holes;                 // into loops
  std::vector<std::uint32_t> index;               // vertex -> its place among those the faces use
  bool runs_back = false;                         // a loop of the last face chained turned straight back
};

// Half-edges to cut, each with the vertices inside it in order from its start.
using Cuts = std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>>;

// A half-edge of a face (from, to) and the face's index; sorted, they find
// the face across a half-edge.
struct FaceOfHalfEdge {
  std::uint32_t from, to;
  std::size_t face;
  bool operator<(const FaceOfHalfEdge& o) const { return from != o.from ? from < o.from : to < o.to; }
};

// Whether cutting half-edge h (of g, or its reverse) at the vertices `inside`
// would turn g's boundary across itself at one of h's ends: a vertex within
// twice `near` of the end lies in no sure direction from it (each lies up to
// `near` off where its planes meet, and off g's plane), so where another
// half-edge of g at that end leaves into the sliver the cut sweeps over, or
// passes within `near` of that vertex, the side of it the vertex falls on,
// so whether the cut carries g across it, is rounding's and projection's. In
// jittered star 8,000 seed 29 a corner that a cluster 1e-6 m higher ended 2.9
// micrometres from where it started (a split's point) left its face's loop
// turning back there within `near`, and the cut put its end into the split's
// other corner's trajectory: in the face across, the spike's side, 1.2
// micrometres off its plane, inside the 0.1 rad tip in its frame, outside it
// in validation's projection, where the face crossed itself. Farther from
// the end the vertex's direction is sure, and a half-edge there through it
// is the seam running on (8,000 seed 14).
bool turns_across_at_end(const State& st, const FaceGroup& g, HalfEdge h,
                         const std::vector<std::pair<double, std::uint32_t>>& inside) {
  const FaceFrame fr = frame_of(g);
  const double near = st.tol().position();
  auto pos = [&](std::uint32_t v) { return fr.to2d(st.vertices[v]); };
  auto cut_in = [&](std::uint32_t v) {
    return v == h.from || v == h.to ||
           std::any_of(inside.begin(), inside.end(), [&](const auto& in) { return in.second == v; });
  };
  return std::any_of(inside.begin(), inside.end(), [&](const auto& in) {
    const glm::dvec2 c = pos(in.second);
    // Whether the half-edge from p (an end of h; u the other) to q turns g
    // across itself.
    auto crosses = [&](glm::dvec2 p, glm::dvec2 u, glm::dvec2 q) {
      if (!(glm::length(c - p) <= 2.0 * near)) return false;
      const double turn = cross(u - p, c - p);
      const bool into = cross(u - p, q - p) * turn > 0.0 && cross(q - p, c - p) * turn > 0.0;
      return into || distance_to_segment(c, p, q) <= near;
    };
    return std::any_of(g.half_edges.begin(), g.half_edges.end(), [&](const HalfEdge& e) {
      for (const auto& [v, w] : {std::pair{e.from, e.to}, std::pair{e.to, e.from}}) {
        if (cut_in(w)) continue;
        if ((v == h.from && crosses(pos(h.from), pos(h.to), pos(w))) ||
            (v == h.to && crosses(pos(h.to), pos(h.from), pos(w))))
          return true;
      }
      return false;
    });
  });
}

// A face whose boundary runs along itself passes a vertex of its own in the
// middle of one of its half-edges: the face of a plane made and eaten at one
// height (an edge between straight-on neighbours that the rule for straight
// runs gives to its neighbour) is a loop of no area along one line and back;
// a plan edit's front can run along the edge it was spliced into and back.
// The rule: such a half-edge is cut at that vertex (where the face runs on
// along the half-edge's line from it, not where it only touches the line at
// a point, as near-touching parts of a plan do), and so is its reverse in the
// face across, so both sides meet vertex to vertex; the parts that run back
// along each other in one face are then a seam, which chaining drops.
void add_own_vertex_cuts(const State& st, const FaceGroup& f, const std::vector<FaceOfHalfEdge>& faces_by_half_edge,
                         ChainScratch& x, Cuts& cuts) {
  x.given.clear();
  for (const HalfEdge& h : f.half_edges)
    if (h.from != h.to) x.given.push_back(h);
  if (x.given.size() < 3) return;
  const FaceFrame fr = frame_of(f);
  const double near = st.tol().position();
  auto pos = [&](std::uint32_t v) { return fr.to2d(st.vertices[v]); };
  x.corners.clear();
  x.links.clear();
  for (const HalfEdge& h : x.given) {
    x.corners.push_back({pos(h.from).x, h.from});
    x.links.push_back({h.from, h.to});
    x.links.push_back({h.to, h.from});
  }
  std::sort(x.links.begin(), x.links.end());
  std::sort(x.corners.begin(), x.corners.end());
  x.corners.erase(std::unique(x.corners.begin(), x.corners.end()), x.corners.end());
  for (const HalfEdge& h : x.given) {
    const glm::dvec2 a = pos(h.from), along = pos(h.to) - a;
    const double length = glm::length(along);
    if (!(length > near)) continue;
    x.inside.clear();
    const auto first = std::lower_bound(x.corners.begin(), x.corners.end(),
                                        std::pair{std::min(a.x, a.x + along.x) - near, std::uint32_t{0}});
    auto on_line = [&](glm::dvec2 p) { return std::abs(cross(along, p - a)) <= near * length; };
    auto runs_along = [&](std::uint32_t v) {
      const glm::dvec2 p = pos(v);
      for (auto l = std::lower_bound(x.links.begin(), x.links.end(), std::pair{v, std::uint32_t{0}});
           l != x.links.end() && l->first == v; ++l)
        if (glm::length(pos(l->second) - p) > near && on_line(pos(l->second))) return true;
      return false;
    };
    const auto last = std::upper_bound(first, x.corners.end(),
                                       std::pair{std::max(a.x, a.x + along.x) + near, ~std::uint32_t{0}});
    for (auto it = first; it != last; ++it) {
      const glm::dvec2 d = pos(it->second) - a;
      const double t = glm::dot(d, along) / length;
      if (t > near && t < length - near && on_line(a + d) && runs_along(it->second)) x.inside.push_back({t, it->second});
    }
    if (x.inside.empty()) continue;
    // Cut, the half-edge runs through those vertices, each up to `near` off
    // its line, so it moves over the sliver between. Where the face only
    // touches the line at a vertex inside that sliver, or within `near` of
    // the sides the cut makes (on either side of them as rounding goes: a
    // vertex lies up to that far off the face's plane, and each projection
    // of the face places it differently), the cut would carry the edge
    // across it and the face would cross itself: the sliver is then a spike
    // of the face thinner than `near`, not a seam, and the half-edge stays
    // whole (jittered star 4,000 seed 38: a valley corner at 64 m per m of
    // rise passes 0.7 micrometres from where an edge collapsed, then meets a
    // corner at 212 m/m at a sharp angle; the spike's other vertex lies 1.3
    // micrometres off its trajectory. 8,000 seed 38: a face's tip, 1.6
    // micrometres wide, ran 5e-7 m beside the cut's new side, outside it in
    // the face's frame but across it in validation's projection).
    auto cut_in = [&](std::uint32_t v) {
      return v == h.from || v == h.to ||
             std::any_of(x.inside.begin(), x.inside.end(), [&](const auto& in) { return in.second == v; });
    };
    auto swept_over = [&](glm::dvec2 c) {
      const glm::dvec2 b = a + along;
      return std::any_of(first, last, [&](const auto& corner) {
        if (cut_in(corner.second)) return false;
        const glm::dvec2 q = pos(corner.second);
        const double sa = cross(b - a, q - a), sb = cross(c - b, q - b), sc = cross(a - c, q - c);
        return (sa > 0.0 && sb > 0.0 && sc > 0.0) || (sa < 0.0 && sb < 0.0 && sc < 0.0) ||
               distance_to_segment(q, a, c) <= near || distance_to_segment(q, c, b) <= near;
      });
    };
    if (std::any_of(x.inside.begin(), x.inside.end(), [&](const auto& in) { return swept_over(pos(in.second)); }))
      continue;
    // So does the half-edge's reverse in the face across.
    const auto across = std::lower_bound(faces_by_half_edge.begin(), faces_by_half_edge.end(),
                                         FaceOfHalfEdge{h.to, h.from, 0});
    if (turns_across_at_end(st, f, h, x.inside) ||
        (across != faces_by_half_edge.end() && across->from == h.to && across->to == h.from &&
         turns_across_at_end(st, st.faces[across->face], h, x.inside)))
      continue;
    std::sort(x.inside.begin(), x.inside.end());
    std::vector<std::uint32_t>& cut = cuts[{h.from, h.to}];
    for (const auto& [t, v] : x.inside) cut.push_back(v);
  }
}

// Appends from -> to, cut where it or its reverse is, and each piece cut
// again where it is itself a cut half-edge. Where three planes meet straight
// on at a horizontal step and one takes the run from both (angles seed 4229),
// the two faces given over each run along themselves, with cuts at different
// vertices (one face's 9 -> 15 at 16, the other's 16 -> 15 at 8); the face
// across 15 -> 9 must meet both, at 16 and at 8. Each piece is shorter than
// its half-edge by more than the clustering distance, so the cutting ends;
// `depth` bounds it anyway.
void append_cut(std::uint32_t from, std::uint32_t to, const Cuts& cuts, std::vector<HalfEdge>& out, std::size_t depth) {
  const auto ahead = cuts.find({from, to});
  const auto back = ahead == cuts.end() ? cuts.find({to, from}) : cuts.end();
  if ((ahead == cuts.end() && back == cuts.end()) || depth > cuts.size()) {
    out.push_back({from, to});
    return;
  }
  auto step = [&](std::uint32_t v) {
    append_cut(from, v, cuts, out, depth + 1);
    from = v;
  };
  if (ahead != cuts.end()) std::for_each(ahead->second.begin(), ahead->second.end(), step);
  if (back != cuts.end()) std::for_each(back->second.rbegin(), back->second.rend(), step);
  append_cut(from, to, cuts, out, depth + 1);
}

// The face's half-edges, cut where they or their reverses are (into x.given).
void cut_half_edges(const FaceGroup& f, const Cuts& cuts, ChainScratch& x) {
  x.given.clear();
  for (const HalfEdge& h : f.half_edges)
    if (h.from != h.to) append_cut(h.from, h.to, cuts, x.given, 0);
}

// Chains a face's half-edges into closed loops (into x.loops). Where the face
// touches itself at a vertex, the loop takes the sharpest turn, so each loop
// stays simple.
void chain_loops(const State& st, const FaceGroup& f, const Cuts& cuts, ChainScratch& x) {
  // Opposite half-edges inside one face are a zero-width seam: drop both.
  // Sorted by (from, to), the half-edges leaving a vertex are one run.
  x.runs_back = false;
  cut_half_edges(f, cuts, x);
  std::sort(x.given.begin(), x.given.end(), half_edge_less);
  x.hs.clear();
  for (std::size_t i = 0; i < x.given.size();) {
    std::size_t j = i + 1;
    while (j < x.given.size() && half_edge_equal(x.given[j], x.given[i])) ++j;
    const HalfEdge back{x.given[i].to, x.given[i].from};
    const auto [lo, hi] = std::equal_range(x.given.begin(), x.given.end(), back, half_edge_less);
    const std::size_t n = j - i, cancel = std::min<std::size_t>(n, static_cast<std::size_t>(hi - lo));
    for (std::size_t k = cancel; k < n; ++k) x.hs.push_back(x.given[i]);
    i = j;
  }
  x.loops.clear();
  const std::vector<HalfEdge>& hs = x.hs;
  if (hs.empty()) return;
  const FaceFrame fr = frame_of(f);
  auto pos = [&](std::uint32_t v) { return fr.to2d(st.vertices[v]); };
  const double near = st.tol().position();
  x.used.assign(hs.size(), 0);
  std::vector<std::uint32_t>& loop = x.loop;
  for (int start = 0; start < static_cast<int>(hs.size()); ++start) {
    if (x.used[start]) continue;
    loop.clear();
    int h = start;
    while (true) {
      x.used[h] = 1;
      loop.push_back(hs[h].from);
      const std::uint32_t v = hs[h].to;
      const auto lo = std::lower_bound(hs.begin(), hs.end(), HalfEdge{v, 0}, half_edge_less);
      auto open = [&](auto it) { return !x.used[it - hs.begin()] || it - hs.begin() == start; };
      int best = -1, choices = 0;
      for (auto it = lo; it != hs.end() && it->from == v; ++it) {
        if (!open(it)) continue;
        best = static_cast<int>(it - hs.begin());
        ++choices;
      }
      // With one way on, the turn is only needed to refuse NaN positions.
      const glm::dvec2 back = pos(hs[h].from) - pos(v);
      const glm::dvec2 only = choices == 1 ? pos(hs[best].to) - pos(v) : glm::dvec2(0.0);
      // Turning straight back along the way in: the face runs along itself.
      x.runs_back = x.runs_back || (glm::dot(back, only) > 0.0 && std::abs(cross(back, only)) <= near * glm::length(only));
      if (choices > 1 || std::isnan(back.x + back.y + only.x + only.y)) {
        double best_turn = 1e300;
        best = -1;
        for (auto it = lo; it != hs.end() && it->from == v; ++it) {
          if (!open(it)) continue;
          const double turn = clockwise_turn(back, pos(it->to) - pos(v));
          if (turn < best_turn) {
            best_turn = turn;
            best = static_cast<int>(it - hs.begin());
          }
        }
      }
      if (best < 0) open_face(f, v, st.vertices[v], st.plan_position);
      if (best == start) break;
      h = best;
    }
    // Most loops pass each vertex once; only those that do not are split.
    bool repeats = false;
    ++x.loop_id;
    for (std::uint32_t v : loop) {
      repeats = repeats || x.seen[v] == x.loop_id;
      x.seen[v] = x.loop_id;
    }
    if (repeats) {
      split_at_repeats(loop, x.loops);
    } else {
      x.loops.emplace_back(loop.begin(), loop.end());
    }
  }
}

// The surface of the sweep's faces, their half-edges cut by `cuts`; the
// faces whose loops turn straight back go to `runs_back`.
Surface assemble(const State& st, const Cuts& cuts, ChainScratch& x, std::vector<std::size_t>& runs_back) {
  Surface s;
  s.faces.reserve(st.faces.size() + st.faces.size() / 4);
  for (std::size_t fi = 0; fi < st.faces.size(); ++fi) {
    const FaceGroup& f = st.faces[fi];
    const FaceFrame fr = frame_of(f);
    chain_loops(st, f, cuts, x);
    if (x.runs_back) runs_back.push_back(fi);
    // Each outer loop (counter-clockwise) is a face of its own, in order.
    const std::size_t first_face = s.faces.size();
    x.pts.clear();
    x.outer_from.clear();
    x.outer_area.clear();
    x.holes.clear();
    for (std::size_t i = 0; i < x.loops.size(); ++i) {
      std::vector<std::uint32_t>& loop = x.loops[i];
      if (loop.size() < 3) continue;
      const std::size_t from = x.pts.size();
      for (auto v : loop) x.pts.push_back(fr.to2d(st.vertices[v]));
      const double a = signed_area(std::span(x.pts).subspan(from));
      if (a > 0.0) {
        x.outer_from.push_back(from);
        x.outer_area.push_back(a);
        s.faces.push_back({f.kind, f.source_edge, {}, f.tag});
        s.faces.back().loops.push_back(std::move(loop));
      } else {
        x.pts.resize(from);
        x.holes.push_back(i);
      }
    }
    x.outer_from.push_back(x.pts.size());
    const std::size_t outers = x.outer_area.size();
    // A hole split off where it touches an outer loop begins at the vertex
    // they share, on that loop's boundary, where the inside test goes either
    // way (angles seed 75421: a triangle of a face's plane that two merging
    // loops fill, pinched at the top where the face's next plane takes over,
    // was dropped as a sliver and left the surface open). So a hole is tested
    // at a vertex no outer loop passes, or else halfway along its first edge.
    if (!x.holes.empty()) {
      ++x.loop_id;
      for (std::size_t i = 0; i < outers; ++i)
        for (std::uint32_t v : s.faces[first_face + i].loops.front()) x.seen[v] = x.loop_id;
    }
    for (std::size_t hole : x.holes) {
      // A hole belongs to the smallest outer loop around it.
      int best = -1;
      const std::vector<std::uint32_t>& h = x.loops[hole];
      const auto own = std::find_if(h.begin(), h.end(), [&](std::uint32_t v) { return x.seen[v] != x.loop_id; });
      const glm::dvec2 q = own != h.end() ? fr.to2d(st.vertices[*own])
                                          : 0.5 * (fr.to2d(st.vertices[h[0]]) + fr.to2d(st.vertices[h[1]]));
      for (std::size_t i = 0; i < outers; ++i) {
        const auto outer = std::span(x.pts).subspan(x.outer_from[i], x.outer_from[i + 1] - x.outer_from[i]);
        if (inside(outer, q) && (best < 0 || x.outer_area[i] < x.outer_area[best])) best = static_cast<int>(i);
      }
      if (best < 0) {
        // A clockwise loop with nothing around it: a sliver of no area.
        continue;
      }
      s.faces[first_face + static_cast<std::size_t>(best)].loops.push_back(std::move(x.loops[hole]));
    }
  }
  // Vertices no face uses (a plan edit's sliver absorbed by the face it grew
  // into, loops of no area) are left out, the rest keep their order.
  constexpr std::uint32_t kUnused = UINT32_MAX;
  std::vector<std::uint32_t>& index = x.index;
  index.assign(st.vertices.size(), kUnused);
  for (const SurfaceFace& f : s.faces)
    for (const auto& loop : f.loops)
      for (std::uint32_t v : loop) index[v] = 0;
  s.vertices.clear();
  s.vertices.reserve(static_cast<std::size_t>(std::count(index.begin(), index.end(), 0u)));
  for (std::size_t v = 0; v < index.size(); ++v)
    if (index[v] != kUnused) {
      index[v] = static_cast<std::uint32_t>(s.vertices.size());
      s.vertices.push_back(st.vertices[v]);
    }
  for (SurfaceFace& f : s.faces)
    for (auto& loop : f.loops)
      for (std::uint32_t& v : loop) v = index[v];
  return s;
}

// Faces rarely run along themselves; only where one does are the cuts
// looked for, and the surface assembled again with them.
Surface build_surface_with(const State& st, ChainScratch& x) {
  std::vector<std::size_t> runs_back;
  Surface s = assemble(st, {}, x, runs_back);
  if (runs_back.empty()) return s;
  std::vector<FaceOfHalfEdge> faces_by_half_edge;
  for (std::size_t f = 0; f < st.faces.size(); ++f)
    for (const HalfEdge& h : st.faces[f].half_edges) faces_by_half_edge.push_back({h.from, h.to, f});
  std::sort(faces_by_half_edge.begin(), faces_by_half_edge.end());
  Cuts cuts;
  for (std::size_t f : runs_back) add_own_vertex_cuts(st, st.faces[f], faces_by_half_edge, x, cuts);
  if (cuts.empty()) return s;
  runs_back.clear();
  return assemble(st, cuts, x, runs_back);
}

}  // namespace

Surface build_surface(const State& st) {
  std::unique_ptr<ChainScratch> x = Spares<ChainScratch>::take();
  x->next_surface(st.vertices.size());
  Surface s = build_surface_with(st, *x);
  Spares<ChainScratch>::give(std::move(x), st.corners.size());
  return s;
}

namespace {

// close_surface's arrays, kept for the thread's next surface (spares.h).
struct CloseScratch {
  // A half-edge, with the one before it in its loop: kept small, since a
  // roof's arrays here are its largest at once.
  struct Half {
    std::uint32_t from, to, prev, next, face;
    std::uint32_t loop;  // in `loops`
    std::uint32_t at;    // `from`'s place in its loop
  };
  std::vector<std::vector<std::uint32_t>*> loops;
  std::vector<Half> halves;
  std::vector<std::uint32_t> start, order, next, tos, twin;
  std::vector<glm::dvec3> normals;
  std::vector<FaceAtEdge> round;
  std::vector<char> in_fan;
};

}  // namespace

void close_surface(Surface& surface, const PlanPosition& plan_position) {
  std::unique_ptr<CloseScratch> scratch = Spares<CloseScratch>::take();
  CloseScratch& arrays = *scratch;
  auto at = [&](std::uint32_t v) { return "vertex " + std::to_string(v) + " " + plan_position(surface.vertices[v]); };
  auto fail = [&](std::uint32_t v, const std::string& what) {
    throw SweepError("sweep: the surface is not closed at " + at(v) + ": " + what, surface.vertices[v].z, {});
  };
  // Every half-edge, with the one before it in its loop: counted first, as
  // reaching past glibc's trim threshold (128 KB) made each sweep of a
  // 200-corner plan give the heap's top back and fault it in again.
  using Half = CloseScratch::Half;
  std::vector<std::vector<std::uint32_t>*>& loops = arrays.loops;
  loops.clear();
  std::size_t count = 0;
  for (SurfaceFace& face : surface.faces)
    for (auto& loop : face.loops) {
      loops.push_back(&loop);
      count += loop.size();
    }
  std::vector<Half>& halves = arrays.halves;
  halves.clear();
  halves.reserve(count);
  for (std::uint32_t f = 0, l = 0; f < surface.faces.size(); ++f)
    for (const auto& loop : surface.faces[f].loops) {
      const auto first = static_cast<std::uint32_t>(halves.size()), m = static_cast<std::uint32_t>(loop.size());
      for (std::uint32_t i = 0; i < m; ++i)
        halves.push_back({loop[i], loop[(i + 1) % m], first + (i + m - 1) % m, first + (i + 1) % m, f, l, i});
      ++l;
    }
  // A hole touching its face's outer loop at a vertex (angles seed 75421: a
  // triangle of the face's plane that two merging loops fill, its apex on the
  // line where the face's next plane takes over) passes the vertex in both
  // loops. The face's corners there are not the loops' own: the way on from a
  // half-edge arriving is the face's half-edge leaving that turns least
  // clockwise from it, as the loops were chained, so the fans round the
  // vertex pass from one loop to the other.
  for (std::uint32_t f = 0, first = 0; f < surface.faces.size(); ++f) {
    const SurfaceFace& face = surface.faces[f];
    std::uint32_t end = first;
    for (const auto& loop : face.loops) end += static_cast<std::uint32_t>(loop.size());
    if (face.loops.size() > 1) {
      std::vector<glm::dvec3> points;
      for (std::uint32_t v : face.loops.front()) points.push_back(surface.vertices[v]);
      const FaceFrame fr = frame_of(glm::normalize(newell_normal(points)));
      auto toward = [&](std::uint32_t a, std::uint32_t b) { return fr.to2d(surface.vertices[b] - surface.vertices[a]); };
      std::map<std::uint32_t, std::vector<std::uint32_t>> leaving;
      for (std::uint32_t g = first; g < end; ++g) leaving[halves[g].from].push_back(g);
      for (std::uint32_t g = first; g < end; ++g) {
        const std::vector<std::uint32_t>& ways = leaving[halves[g].to];
        if (ways.size() < 2) continue;
        const glm::dvec2 back = toward(halves[g].to, halves[g].from);
        std::uint32_t best = halves[g].next;
        double best_turn = 1e300;
        for (std::uint32_t o : ways)
          if (const double turn = clockwise_turn(back, toward(halves[o].from, halves[o].to)); turn < best_turn) {
            best_turn = turn;
            best = o;
          }
        halves[g].next = best;
        halves[best].prev = g;
      }
    }
    first = end;
  }
  // The half-edges grouped by `from`, sorted by `to`, then in the order given:
  // counted into one bucket per vertex, then each (small) bucket sorted, and
  // their `to`s beside them. A search over all half-edges at once cost most of
  // a small roof's time in mispredicted branches.
  std::vector<std::uint32_t>& start = arrays.start;
  start.assign(surface.vertices.size() + 1, 0);
  for (const Half& h : halves) ++start[h.from + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t>& order = arrays.order;
  order.resize(halves.size());
  arrays.next.assign(start.begin(), start.end() - 1);
  for (std::uint32_t g = 0; g < halves.size(); ++g) order[arrays.next[halves[g].from]++] = g;
  for (std::size_t v = 0; v + 1 < start.size(); ++v)
    std::sort(order.begin() + start[v], order.begin() + start[v + 1], [&](std::uint32_t a, std::uint32_t b) {
      return std::pair{halves[a].to, a} < std::pair{halves[b].to, b};
    });
  std::vector<std::uint32_t>& tos = arrays.tos;
  tos.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) tos[i] = halves[order[i]].to;
  auto run = [&](std::uint32_t v, std::uint32_t a) {
    const auto [lo, hi] = std::equal_range(tos.begin() + start[v], tos.begin() + start[v + 1], a);
    return std::span<const std::uint32_t>(order).subspan(static_cast<std::size_t>(lo - tos.begin()),
                                                          static_cast<std::size_t>(hi - lo));
  };
  std::vector<glm::dvec3>& normals = arrays.normals;  // per face, made when a pinch needs them
  normals.clear();
  auto normal = [&](std::uint32_t f) {
    if (normals.empty()) {
      normals.reserve(surface.faces.size());
      std::vector<glm::dvec3> points;
      for (const SurfaceFace& face : surface.faces) {
        points.clear();
        for (std::uint32_t v : face.loops.front()) points.push_back(surface.vertices[v]);
        normals.push_back(glm::normalize(newell_normal(points)));
      }
    }
    return normals[f];
  };
  // Each half-edge meets its twin, a reverse; where parts of the solid touch
  // along an edge it has several each way, paired round it (round_edge.h).
  std::vector<std::uint32_t>& twin = arrays.twin;
  twin.resize(halves.size());
  std::vector<std::vector<std::uint32_t>> welded;  // per edge with several faces each way: its halves running from -> to
  std::vector<FaceAtEdge>& round = arrays.round;
  for (std::size_t i = 0; i < order.size();) {
    const Half& h = halves[order[i]];
    const auto ahead = run(h.from, h.to), back = run(h.to, h.from);
    i += ahead.size();
    if (back.empty()) fail(h.from, "no face runs back along its edge to " + at(h.to));
    if (ahead.size() > back.size()) fail(h.from, "two faces run the same way along its edge to " + at(h.to));
    if (ahead.size() < back.size()) fail(h.to, "two faces run the same way along its edge to " + at(h.from));
    if (ahead.size() == 1) {
      twin[ahead[0]] = back[0];
      continue;
    }
    if (h.from > h.to) continue;  // paired from the other end
    round.clear();
    for (const auto side : {ahead, back})
      for (std::uint32_t g : side) round.push_back({normal(halves[g].face), halves[g].from == h.from});
    const auto twins = twins_round_edge(surface.vertices[h.to] - surface.vertices[h.from], round);
    if (!twins) fail(h.from, "faces along its edge to " + at(h.to) + " overlap or fold over each other");
    auto given = [&](std::size_t k) { return k < ahead.size() ? ahead[k] : back[k - ahead.size()]; };
    for (std::size_t k = 0; k < round.size(); ++k) twin[given(k)] = given((*twins)[k]);
    welded.emplace_back(ahead.begin(), ahead.end());
  }
  // Round a vertex the faces form fans: from v -> a, the face on its right
  // holds the twin of the half-edge before v -> a in its loop. Where parts of
  // the solid touch at the vertex (or along an edge through it) it has a fan
  // for each. The surface stays a closed 2-manifold (and the solid the same
  // point set) when every fan after the first (the one holding v's lowest
  // `to`) has a copy of v of its own.
  std::vector<char>& in_fan = arrays.in_fan;
  in_fan.assign(halves.size(), 0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (in_fan[order[i]]) continue;
    const std::uint32_t v = halves[order[i]].from;
    const bool copy = i > 0 && halves[order[i - 1]].from == v;
    const std::uint32_t id = copy ? static_cast<std::uint32_t>(surface.vertices.size()) : v;
    if (copy) surface.vertices.push_back(surface.vertices[v]);
    std::uint32_t g = order[i];
    do {
      in_fan[g] = 1;
      (*loops[halves[g].loop])[halves[g].at] = id;
      g = twin[halves[g].prev];
    } while (!in_fan[g]);
  }
  // Parts that touch along an edge and are joined round both its ends (a
  // hole's ledge stepping onto the outline's line beside its soffit) keep
  // both ends in one fan each: the edge would then carry its pairs between
  // the same two vertices. Each pair after the first gets a point of its own
  // halfway along, in both its faces, so every edge has one face each way.
  struct Insert {
    std::vector<std::uint32_t>* loop;
    std::uint32_t after;
    std::uint32_t v;
  };
  std::vector<Insert> inserts;
  for (const std::vector<std::uint32_t>& edge : welded) {
    auto ends = [&](std::uint32_t g) {
      const Half& h = halves[g];
      const Half& n = halves[h.next];
      return std::pair{(*loops[h.loop])[h.at], (*loops[n.loop])[n.at]};
    };
    for (std::size_t k = 1; k < edge.size(); ++k) {
      const auto [a, b] = ends(edge[k]);
      bool shared = false;
      for (std::size_t j = 0; j < k; ++j) shared = shared || ends(edge[j]) == std::pair{a, b};
      if (!shared) continue;
      const auto mid = static_cast<std::uint32_t>(surface.vertices.size());
      surface.vertices.push_back(0.5 * (surface.vertices[a] + surface.vertices[b]));
      for (const std::uint32_t g : {edge[k], twin[edge[k]]}) inserts.push_back({loops[halves[g].loop], halves[g].at, mid});
    }
  }
  // Later places first, so earlier ones stay where they are.
  std::sort(inserts.begin(), inserts.end(), [](const Insert& x, const Insert& y) {
    return x.loop != y.loop ? x.loop < y.loop : x.after > y.after;
  });
  for (const Insert& i : inserts) i.loop->insert(i.loop->begin() + i.after + 1, i.v);
  Spares<CloseScratch>::give(std::move(scratch), surface.vertices.size());
}

}  // namespace procex::engine
