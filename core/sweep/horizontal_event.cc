#include "core/sweep/horizontal_event.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/chain_overlay.h"
#include "core/geom/error.h"
#include "core/geom/point_grid.h"
#include "core/geom/tolerances.h"
#include "core/geom/turn.h"
#include "core/sweep/driver.h"
#include "core/sweep/settle.h"

namespace procex::engine {
namespace {

// The live cross-section as loops of corners, in corner order.
std::vector<std::vector<int>> live_loops(const State& st) {
  std::vector<char> seen(st.corners.size(), 0);
  std::vector<std::vector<int>> loops;
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c) {
    if (!st.corners[c].alive || seen[c]) continue;
    std::vector<int> loop;
    for (int x = c; !seen[x]; x = st.corners[x].next) {
      seen[x] = 1;
      loop.push_back(x);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Where straight-on neighbours step by different amounts, the nested sweep
// puts a joint between them: an edge of no length at their shared vertex,
// across their line, that does not step. Rising, it stays put while they move
// apart, and its top is the jog between their new lines. Without it the two
// would be one ambiguous run (paper 4.5) taking one step, or, nearly straight,
// a corner racing along their line, and the jog would be lost or a sliver.
struct Joint {
  int prev = kNone, next = kNone;   // the nested sources it joins
  glm::dvec2 point{0.0}, dir{0.0};  // its line (dir: from prev's new line to next's)
};

// The nested sweep of the cross-section and how its parts map back.
struct Nested {
  State st;
  std::vector<int> span_edge;              // nested source j -> the outer edge it offsets (kNone: a joint)
  std::map<int, Joint> joints;             // nested source -> the joint it is
  std::vector<std::uint32_t> base_vertex;  // nested vertex i < size -> outer vertex
  std::vector<std::uint32_t> top;          // nested corner -> its vertex at the top
  double reach = 0.0;                      // the nested sweep's height: the largest step

  // Nested source j's slope: its step over the reach (0: the edge does not step).
  double slope(int j) const { return st.edges[st.sources[j].edge].plane.k; }
};

// Loads one loop of the cross-section into the nested sweep, a joint at each
// straight corner whose edges step differently. Steps closer than the
// clustering distance are one step: the jog between them would be no wider.
void load_nested_loop(Nested& n, const State& st, const std::vector<int>& loop, const std::vector<std::uint32_t>& at,
                      const std::map<int, SourceStep>& steps, int li) {
  std::vector<glm::dvec2> points;
  std::vector<double> slopes;
  for (int c : loop) {
    const auto step = steps.find(st.edges[st.corners[c].next_edge].source);
    points.emplace_back(st.vertices[at[c]]);
    // Rising `reach`, an edge with slope step / reach moves inward by its step.
    slopes.push_back(step == steps.end() ? 0.0 : step->second.inward / n.reach);
  }
  const std::vector<glm::dvec2> dirs = edge_directions(points, li);
  const double near = st.tol().position();
  const std::size_t m = loop.size();
  std::vector<glm::dvec2> all_points, all_dirs;
  std::vector<double> all_slopes;
  const int s0 = static_cast<int>(n.st.sources.size());
  auto add = [&](glm::dvec2 p, glm::dvec2 d, double k, int edge, std::uint32_t v) {
    all_points.push_back(p);
    all_dirs.push_back(d);
    all_slopes.push_back(k);
    Source src;
    src.id = static_cast<std::int32_t>(n.span_edge.size());
    n.st.sources.push_back(src);
    n.span_edge.push_back(edge);
    n.base_vertex.push_back(v);
  };
  auto differ = [&](std::size_t a, std::size_t b) { return std::abs(slopes[a] - slopes[b]) * n.reach > near; };
  // Between edges that step differently, the weighted skeleton's corner runs
  // along their line by the difference over the sine of its turn. Where the
  // corner lies within the mesh's distance tolerance of its neighbours' line
  // (kMeshDistanceRelative of the extent, above the clustering distance of
  // every scale the sweep tries but its loosest), that run passes the
  // shorter edge, which then lies within that distance of the other's line
  // all along: the exact answer takes the step from one of them (or gives it
  // to both) and leaves a sliver no wider than that distance, which the mesh
  // cannot tell from a touch (OSM way 37054313: a soffit 0.8 mm under the
  // roof over it, seen as a self-intersection). The output cannot tell such
  // a corner from a straight one, so it takes a joint as a straight one does.
  const double resolved = std::max(near, kMeshDistanceRelative * st.tol().scale);
  auto jointed = [&](std::size_t j) {
    const std::size_t before = (j + m - 1) % m;
    return runs_straight(points, dirs, j, differ(j, before) ? resolved : near);
  };
  // Entered at a corner that takes no joint, each run of straight corners is seen in order.
  std::size_t start = 0;
  while (start < m && jointed(start)) ++start;
  if (start == m) throw SweepError("sweep: a loop of the cross-section has no corner", st.height, {});
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t j = (start + i) % m, before = (j + m - 1) % m;
    const int c = loop[j];
    if (i > 0 && jointed(j)) {
      if (!differ(j, before)) {
        slopes[j] = slopes[before];
      } else {
        const glm::dvec2 across =
            glm::normalize(glm::dvec2(-dirs[before].y, dirs[before].x) + glm::dvec2(-dirs[j].y, dirs[j].x));
        const int joint = s0 + static_cast<int>(all_points.size());
        n.joints[joint] = {joint - 1, joint + 1, points[j], slopes[j] > slopes[before] ? across : -across};
        add(points[j], n.joints[joint].dir, 0.0, kNone, at[c]);
      }
    }
    add(points[j], dirs[j], slopes[j], st.corners[c].next_edge, at[c]);
  }
  load_edges(n.st, all_points, all_dirs, all_slopes, std::vector<std::string>(all_points.size()), s0);
}

void sweep_nested(Nested& n, State& st, const std::vector<std::vector<int>>& loops,
                  const std::vector<std::uint32_t>& at, const std::map<int, SourceStep>& steps) {
  FaceGroup base;
  base.kind = FaceKind::Base;
  n.st.base_face = 0;
  n.st.faces.push_back(base);
  for (std::size_t li = 0; li < loops.size(); ++li) {
    try {
      load_nested_loop(n, st, loops[li], at, steps, static_cast<int>(li));
    } catch (const InputError&) {
      throw SweepError("sweep: corners coincide where profiles step sideways at height " + std::to_string(st.height),
                       st.height, {});
    }
  }
  // A corner at a joint starts on the line of the edge across the joint, and
  // leaves it rising: it does not run into that edge where it starts.
  EventQueue queue;
  for (int c = 0; c < static_cast<int>(n.st.corners.size()); ++c) {
    const Corner& k = n.st.corners[c];
    std::vector<int> resolved;
    if (auto j = n.joints.find(n.st.edges[k.prev_edge].source); j != n.joints.end())
      resolved.push_back(n.st.sources[j->second.prev].edge);
    if (auto j = n.joints.find(n.st.edges[k.next_edge].source); j != n.joints.end())
      resolved.push_back(n.st.sources[j->second.next].edge);
    queue.schedule(n.st, c, resolved);
  }
  ProfileEvents none;
  run_events(n.st, queue, none);
  n.st.height = n.reach;
  n.top.assign(n.st.corners.size(), 0);
  for (int c = 0; c < static_cast<int>(n.st.corners.size()); ++c)
    if (n.st.corners[c].alive) n.top[c] = n.st.vertex_now(c);
  for (int c = 0; c < static_cast<int>(n.st.corners.size()); ++c) {
    const Corner& k = n.st.corners[c];
    if (k.alive) n.st.emit_top(k.next_edge, n.top[c], n.top[k.next]);
  }
}

// Nested vertices flattened onto the sweep plane at height z. A vertex on the
// face of an edge that does not step (a strip of no width) is put back on
// that edge's line, where it belongs: the nested sweep computes it to its own
// precision, and the faces at z must find it on that line, not beside it.
// Vertices that land on one point (within the clustering distance) are one
// vertex: a corner between edges that do not step stays where it is.
std::vector<std::uint32_t> flatten_vertices(const Nested& n, State& st, double z) {
  constexpr int kMany = -2;
  std::vector<int> line(n.st.vertices.size(), kNone);  // nested vertex -> the outer edge whose line it is on
  for (const FaceGroup& f : n.st.faces) {
    if (f.kind != FaceKind::Side || n.slope(f.source_edge) != 0.0) continue;
    const int e = n.span_edge[f.source_edge];
    if (e == kNone) continue;  // a joint's vertices are its neighbours'
    for (const HalfEdge& h : f.half_edges)
      for (std::uint32_t v : {h.from, h.to}) line[v] = line[v] == kNone || line[v] == e ? e : kMany;
  }
  PointGrid grid(st.tol().position());
  std::vector<std::uint32_t> out(n.st.vertices.size());
  for (std::size_t i = 0; i < n.base_vertex.size(); ++i) {
    out[i] = n.base_vertex[i];
    grid.add(glm::dvec2(n.st.vertices[i]), out[i]);
  }
  for (std::size_t i = n.base_vertex.size(); i < out.size(); ++i) {
    glm::dvec2 p(n.st.vertices[i]);
    if (line[i] >= 0) {
      const Plane& pl = st.edges[line[i]].plane;
      p -= pl.n * pl.signed_distance(p, z);
    }
    if (auto v = grid.first_near(p)) {
      out[i] = *v;
      continue;
    }
    out[i] = st.vertex_at(p, z);
    grid.add(p, out[i]);
  }
  return out;
}

// An edge of the new cross-section as the nested sweep left it: from the top
// of a nested corner to the top of the next, on nested source `source`.
struct TopEdge {
  std::uint32_t from, to;
  int source;
};

// Everything at z overlaid: the flattened nested faces of the edges that
// step, the new cross-section's edges, and every segment at z in any face
// (the ends of the faces below, what plan edits wrote). Each of those is cut
// where another crosses or touches it, so all faces meet vertex to vertex.
struct AtHeight {
  ChainOverlay overlay;
  std::vector<std::uint32_t> global;  // overlay point -> vertex
  std::vector<int> stepping;          // group -> the outer edge whose flattened face it is
  std::size_t first_top = 0;          // overlay segment of the first TopEdge
};

AtHeight overlay_at_height(State& st, const Nested& n, const std::vector<std::uint32_t>& vertex,
                           const std::vector<TopEdge>& tops, double z) {
  AtHeight h;
  std::unordered_map<std::uint32_t, std::uint32_t> local_of;
  std::vector<glm::dvec2> points;
  auto local = [&](std::uint32_t v) {
    auto [it, fresh] = local_of.try_emplace(v, static_cast<std::uint32_t>(h.global.size()));
    if (fresh) {
      h.global.push_back(v);
      points.emplace_back(st.vertices[v]);
    }
    return it->second;
  };
  std::vector<OverlaySegment> segments;
  std::vector<std::pair<std::size_t, std::size_t>> written;  // segment i < size: (face, half-edge)
  auto at_z = [&](std::uint32_t v) { return std::abs(st.vertices[v].z - z) <= st.tol().height(); };
  for (std::size_t f = 0; f < st.faces.size(); ++f) {
    const std::vector<HalfEdge>& hs = st.faces[f].half_edges;
    for (std::size_t i = 0; i < hs.size(); ++i)
      if (hs[i].from != hs[i].to && at_z(hs[i].from) && at_z(hs[i].to)) {
        segments.push_back({local(hs[i].from), local(hs[i].to), -1});
        written.push_back({f, i});
      }
  }
  h.first_top = segments.size();
  for (const TopEdge& t : tops) segments.push_back({local(t.from), local(t.to), -1});
  // An edge that does not step flattens to a strip of no area, which covers nothing.
  std::map<int, int> group_of;
  for (const FaceGroup& f : n.st.faces) {
    if (f.kind != FaceKind::Side || n.slope(f.source_edge) == 0.0) continue;
    const int e = n.span_edge[f.source_edge];
    auto [it, fresh] = group_of.try_emplace(e, static_cast<int>(h.stepping.size()));
    if (fresh) h.stepping.push_back(e);
    for (const HalfEdge& he : f.half_edges) {
      const std::uint32_t a = vertex[he.from], b = vertex[he.to];
      if (a != b) segments.push_back({local(a), local(b), it->second});
    }
  }

  h.overlay = overlay_chains(std::move(points), segments, st.tol().position());
  for (std::size_t i = h.global.size(); i < h.overlay.points.size(); ++i)
    h.global.push_back(st.vertex_at(h.overlay.points[i], z));

  for (std::size_t next = 0; next < written.size();) {
    const std::size_t f = written[next].first;
    std::vector<HalfEdge> cut;
    const std::vector<HalfEdge>& hs = st.faces[f].half_edges;
    for (std::size_t i = 0; i < hs.size(); ++i) {
      if (next == written.size() || written[next] != std::pair{f, i}) {
        cut.push_back(hs[i]);
        continue;
      }
      const std::vector<std::uint32_t>& chain = h.overlay.pieces[next++];
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) cut.push_back({h.global[chain[k]], h.global[chain[k + 1]]});
    }
    st.faces[f].half_edges = std::move(cut);
  }
  return h;
}

// The horizontal faces at z. The flattened nested faces of the edges that
// step cover the old cross-section less the new one (ledges, winding +1) and
// the new less the old (soffits, winding -1); where neighbours step different
// ways they fold over each other and cancel, and where grown steps overlap
// they count once: every cell of non-zero winding is one face, of an edge
// covering it.
void horizontal_faces(State& st, const AtHeight& h, const std::map<int, SourceStep>& steps, double z) {
  std::map<int, int> face_of;  // group -> its horizontal face
  for (const OverlayCell& cell : h.overlay.cells) {
    auto [it, fresh] = face_of.try_emplace(cell.owner, 0);
    if (fresh) {
      const int e = h.stepping[cell.owner];
      const auto step = steps.find(st.edges[e].source);
      FaceGroup f;
      f.kind = FaceKind::Side;
      f.source_edge = st.edges[e].source_id;
      f.tag = step == steps.end() ? st.faces[st.edges[e].face].tag : step->second.step_tag;
      f.outward = {0.0, 0.0, cell.winding > 0 ? 1.0 : -1.0};
      f.origin = {0.0, 0.0, z};
      it->second = static_cast<int>(st.faces.size());
      st.faces.push_back(std::move(f));
    }
    // A soffit is seen from below: its cycles run the other way.
    std::vector<HalfEdge>& hs = st.faces[it->second].half_edges;
    const std::size_t m = cell.loop.size();
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t a = h.global[cell.loop[k]], b = h.global[cell.loop[(k + 1) % m]];
      hs.push_back(cell.winding > 0 ? HalfEdge{a, b} : HalfEdge{b, a});
    }
  }
}

// A loop of the new cross-section: each vertex with the nested source of the edge leaving it.
using SectionLoop = std::vector<std::pair<std::uint32_t, int>>;

// The new cross-section: the outline of where the nested sweep's top winds
// round at least once. Where grown steps ran into each other at the top (a
// dormer's front meeting its neighbour's at a concave corner), the top
// overlaps itself; its outline does not.
std::vector<SectionLoop> new_cross_section(const AtHeight& h, const std::vector<TopEdge>& tops, double near, double z) {
  const ChainOverlay& o = h.overlay;
  std::vector<OverlaySegment> pieces;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> source_of;  // piece either way -> nested source
  for (std::size_t t = 0; t < tops.size(); ++t) {
    const auto& chain = o.pieces[h.first_top + t];
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      pieces.push_back({chain[k], chain[k + 1], 0});
      source_of.try_emplace({chain[k], chain[k + 1]}, tops[t].source);
      source_of.try_emplace({chain[k + 1], chain[k]}, tops[t].source);
    }
  }
  // Already cut against each other, the pieces make no new points.
  const ChainOverlay inside = overlay_chains(o.points, pieces, near);
  auto open = [&] { return SweepError("sweep: the cross-section after a horizontal step is not closed", z, {}); };
  if (inside.points.size() != o.points.size()) throw open();
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> outline;
  for (const OverlayCell& cell : inside.cells) {
    if (cell.winding < 1) continue;
    for (std::size_t k = 0; k < cell.loop.size(); ++k) {
      const std::uint32_t a = cell.loop[k], b = cell.loop[(k + 1) % cell.loop.size()];
      if (auto back = outline.find({b, a}); back != outline.end()) {
        if (--back->second == 0) outline.erase(back);
      } else {
        ++outline[{a, b}];
      }
    }
  }
  // Chain the outline; where it touches itself, leave each point by the
  // first way clockwise from the way in, so every loop stays simple.
  std::multimap<std::uint32_t, std::uint32_t> out;
  for (const auto& [edge, count] : outline)
    for (int i = 0; i < count; ++i) out.emplace(edge.first, edge.second);
  std::vector<SectionLoop> loops;
  while (!out.empty()) {
    SectionLoop loop;
    auto it = out.begin();
    const std::uint32_t start = it->first;
    std::uint32_t from = start, to = it->second;
    out.erase(it);
    while (true) {
      const auto source = source_of.find({from, to});
      if (source == source_of.end()) throw open();
      loop.push_back({from, source->second});
      if (to == start) break;
      auto [lo, hi] = out.equal_range(to);
      if (lo == hi) throw open();
      auto best = lo;
      double best_turn = 1e300;
      for (auto x = lo; x != hi; ++x) {
        const double turn = clockwise_turn(o.points[from] - o.points[to], o.points[x->second] - o.points[to]);
        if (turn < best_turn) {
          best_turn = turn;
          best = x;
        }
      }
      from = to;
      to = best->second;
      out.erase(best);
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

void apply_horizontal_run(State& st, EventQueue& queue, ProfileEvents& profile_events,
                          const std::map<int, SourceStep>& steps) {
  const double z = st.height;
  const std::vector<std::vector<int>> loops = live_loops(st);
  std::vector<std::uint32_t> at(st.corners.size(), 0);
  for (const auto& loop : loops)
    for (int c : loop) at[c] = st.vertex_now(c);

  SweepOptions options;
  for (const auto& [s, step] : steps) options.max_height = std::max(options.max_height.value_or(0.0), std::abs(step.inward));
  options.ambiguity = st.options().ambiguity;
  // What meets at the nested sweep's top is not its to settle: an edge that
  // a step reaches exactly there (a 1 m edge beside a 1 m ledge) shrinks to
  // nothing at the top, and its neighbours, straight on, would be settled by
  // the nested slopes (the steps, paper 4.5), giving the run to the edge
  // that steps least whatever plane follows it. Whether the nested sweep saw
  // that event at all hung on rounding (angles seed 1586: moved to (5e5,
  // 5e6), another edge took the run). It stops a clustering distance short
  // of the top; the new cross-section's corners are settled by the planes
  // above it.
  const double reach = *options.max_height;
  options.max_height = reach - st.tol().height();
  Nested n{State(st.tol(), options, st.budget()), {}, {}, {}, {}, reach};
  sweep_nested(n, st, loops, at, steps);
  const std::vector<std::uint32_t> vertex = flatten_vertices(n, st, z);

  // The faces below end on the cross-section.
  for (const auto& loop : loops)
    for (int c : loop) st.emit_top(st.corners[c].next_edge, at[c], at[st.corners[c].next]);

  // The planes above: each edge's line moved by its step, with the slope its
  // profile continues with. An edge that neither steps nor turns goes on.
  std::map<int, int> above;  // outer edge -> its plane above the run
  auto edge_above = [&](int j) {
    const int e = n.span_edge[j];
    auto [it, fresh] = above.try_emplace(e, e);
    if (!fresh) return it->second;
    const Edge old = st.edges[e];
    const std::string old_tag = st.faces[old.face].tag;
    const auto step = steps.find(old.source);
    const double k = step == steps.end() ? old.plane.k : step->second.slope;
    const std::string tag = step == steps.end() ? old_tag : step->second.tag;
    const double moved = n.slope(j) * n.reach;
    if (moved != 0.0 || k != old.plane.k || tag != old_tag) {
      const glm::dvec2 on_line = old.plane.n * (old.plane.offset_at(z) + moved);
      it->second = st.add_edge(on_line, z, old.dir, k, old.source, tag);
    }
    return it->second;
  };
  // A joint's jog is the end of the part that stands out: of the two
  // neighbours, the one whose line stepped further out (a soffit's eaves, a
  // fascia, the wall beside a ledge). It turns round that end as it would
  // round a corner: on that neighbour's plane above, turned across the line,
  // as a source of its own that follows the rest of that edge's profile, and
  // its face is that edge's. The paper's rule for a straight run (4.5: one
  // plane takes the run, the one the volume rule picks) does not apply: the
  // jog is not on the run's line, and where both neighbours rise at one
  // slope (walls above a ledge and a fascia) it could not choose.
  std::map<int, int> joint_above;  // nested joint -> its plane above the run
  auto plane_above = [&](int j) {
    const auto joint = n.joints.find(j);
    if (joint == n.joints.end()) return edge_above(j);
    auto [it, fresh] = joint_above.try_emplace(j, kNone);
    if (!fresh) return it->second;
    const int pick = n.slope(joint->second.prev) < n.slope(joint->second.next) ? edge_above(joint->second.prev)
                                                                               : edge_above(joint->second.next);
    const int s = static_cast<int>(st.sources.size());
    st.sources.push_back(st.sources[st.edges[pick].source]);
    it->second = st.add_edge(joint->second.point, z, joint->second.dir, st.edges[pick].plane.k, s,
                             st.faces[st.edges[pick].face].tag);
    profile_events.schedule(st, s);
    return it->second;
  };

  // The nested sweep's top, outlined, is the new cross-section.
  std::vector<TopEdge> tops;
  for (std::size_t c = 0; c < n.st.corners.size(); ++c) {
    const Corner& k = n.st.corners[c];
    if (!k.alive) continue;
    const std::uint32_t a = vertex[n.top[c]], b = vertex[n.top[k.next]];
    if (a != b) tops.push_back({a, b, n.st.edges[k.next_edge].source});
  }
  // A corner whose vertex and planes the new cross-section has too goes on:
  // its events below are still its events. One made at this height (a plan
  // edit's) has none yet, and one scheduled before any plane leaned out never
  // listed the splits that leaning out allows.
  std::map<std::tuple<std::uint32_t, int, int>, int> kept_at;  // (vertex, prev plane, next plane) -> old corner
  for (const auto& loop : loops)
    for (int c : loop) {
      const Corner& k = st.corners[c];
      if (st.vertices[k.origin].z < z - st.tol().height() && queue.knows_outward(st, c))
        kept_at.emplace(std::tuple{at[c], k.prev_edge, k.next_edge}, c);
    }
  std::vector<int> old_next(st.corners.size(), kNone);
  for (const auto& loop : loops)
    for (int c : loop) {
      old_next[c] = st.corners[c].next;
      st.corners[c].alive = false;
    }
  const AtHeight h = overlay_at_height(st, n, vertex, tops, z);
  horizontal_faces(st, h, steps, z);
  std::vector<int> made, kept;
  for (const SectionLoop& loop : new_cross_section(h, tops, st.tol().position(), z)) {
    const std::size_t m = loop.size();
    std::vector<int> corners;
    for (std::size_t i = 0; i < m; ++i) {
      const auto [v, source] = loop[i];
      const int prev = plane_above(loop[(i + m - 1) % m].second), next = plane_above(source);
      const std::uint32_t to = h.global[loop[(i + 1) % m].first];
      st.faces[st.edges[next].face].half_edges.push_back({h.global[v], to});
      if (prev == next) continue;
      const auto same = kept_at.find({h.global[v], prev, next});
      if (same == kept_at.end()) {
        const int c = st.add_corner(prev, next, h.global[v]);
        made.push_back(c);
        corners.push_back(c);
        continue;
      }
      // It starts again here, on the line it moved along.
      Corner& k = st.corners[same->second];
      k.origin = h.global[v];
      k.base = glm::dvec2(st.vertices[k.origin]);
      k.base_z = st.vertices[k.origin].z;
      k.alive = true;
      kept.push_back(same->second);
      corners.push_back(same->second);
      kept_at.erase(same);
    }
    if (corners.size() < 2) throw SweepError("sweep: a loop of the cross-section after a horizontal step has no corners", z, {});
    for (std::size_t i = 0; i < corners.size(); ++i) st.link(corners[i], corners[(i + 1) % corners.size()]);
  }
  std::vector<int> live;
  settle(st, made, live);
  std::vector<char> fresh(st.corners.size(), 0);
  for (int c : live) {
    queue.schedule(st, c);
    queue.schedule_edge_event(st, st.corners[c].prev);
    fresh[c] = 1;
  }
  // A kept corner already waits for every plane made below this height. The
  // planes made here are new to it: those above the run, and a plan edit's
  // inserted edges, which the edit leaves to this run to schedule (only the
  // planes above would miss its splits with those). Edges are made in order
  // of height, so the ones made here are the last.
  std::vector<int> planes_here;
  for (int e = static_cast<int>(st.edges.size()) - 1;
       e >= 0 && st.faces[st.edges[e].face].origin.z >= z - st.tol().height(); --e)
    planes_here.push_back(e);
  for (int c : kept) {
    if (!st.corners[c].alive) continue;
    const int next = st.corners[c].next;
    // A new neighbour schedules the event with its previous corner itself.
    if (next != old_next[c] && !fresh[next]) queue.schedule_edge_event(st, c);
    queue.schedule_splits(st, c, planes_here);
  }
}

}  // namespace procex::engine
