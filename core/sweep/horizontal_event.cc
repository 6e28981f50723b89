#include "core/sweep/horizontal_event.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/chain_overlay.h"
#include "core/geom/error.h"
#include "core/geom/point_grid.h"
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

// The nested sweep of the cross-section and how its parts map back.
struct Nested {
  State st;
  std::vector<int> span_edge;                // nested source j -> the outer edge it offsets
  std::vector<std::uint32_t> base_vertex;    // nested vertex i < size -> outer vertex
  std::vector<std::uint32_t> top;            // nested corner -> its vertex at the top
  double reach = 0.0;                        // the nested sweep's height: the largest step
};

void sweep_nested(Nested& n, State& st, const std::vector<std::vector<int>>& loops,
                  const std::vector<std::uint32_t>& at, const std::map<int, SourceStep>& steps) {
  FaceGroup base;
  base.kind = FaceKind::Base;
  n.st.base_face = 0;
  n.st.faces.push_back(base);
  for (std::size_t li = 0; li < loops.size(); ++li) {
    std::vector<glm::dvec2> points;
    std::vector<double> slopes;
    const int s0 = static_cast<int>(n.st.sources.size());
    for (int c : loops[li]) {
      const int e = st.corners[c].next_edge;
      const auto step = steps.find(st.edges[e].source);
      points.emplace_back(st.vertices[at[c]]);
      // Rising `reach`, an edge with slope step / reach moves inward by its step.
      slopes.push_back(step == steps.end() ? 0.0 : step->second.inward / n.reach);
      Source src;
      src.id = static_cast<std::int32_t>(n.span_edge.size());
      n.st.sources.push_back(src);
      n.span_edge.push_back(e);
      n.base_vertex.push_back(at[c]);
    }
    try {
      load_loop(n.st, points, std::move(slopes), std::vector<std::string>(points.size()), s0, static_cast<int>(li));
    } catch (const InputError&) {
      throw SweepError("sweep: corners coincide where profiles step sideways at height " + std::to_string(st.height),
                       st.height, {});
    }
  }
  EventQueue queue;
  schedule_all(n.st, queue);
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
    if (f.kind != FaceKind::Side || n.st.edges[n.st.sources[f.source_edge].edge].plane.k != 0.0) continue;
    const int e = n.span_edge[f.source_edge];
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
    out[i] = st.add_vertex({p, z});
    grid.add(p, out[i]);
  }
  return out;
}

// The horizontal faces at z. The flattened nested faces of the edges that
// step cover the old cross-section less the new one (ledges, winding +1) and
// the new less the old (soffits, winding -1); where neighbours step different
// ways they fold over each other, so they are overlaid and only the cells of
// non-zero winding are kept, each in the face of an edge covering it. Every
// segment at z in any face (the ends of the faces below, the starts of those
// above, what plan edits wrote) is cut where another crosses or touches it,
// so all faces meet vertex to vertex.
void horizontal_faces(State& st, const Nested& n, const std::vector<std::uint32_t>& vertex,
                      const std::map<int, SourceStep>& steps, double z) {
  std::vector<std::uint32_t> global;
  std::unordered_map<std::uint32_t, std::uint32_t> local_of;
  std::vector<glm::dvec2> points;
  auto local = [&](std::uint32_t v) {
    auto [it, fresh] = local_of.try_emplace(v, static_cast<std::uint32_t>(global.size()));
    if (fresh) {
      global.push_back(v);
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
  // An edge that does not step flattens to a strip of no area, which covers nothing.
  std::vector<int> stepping;  // group -> outer edge
  std::map<int, int> group_of;
  for (const FaceGroup& f : n.st.faces) {
    if (f.kind != FaceKind::Side || n.st.edges[n.st.sources[f.source_edge].edge].plane.k == 0.0) continue;
    const int e = n.span_edge[f.source_edge];
    auto [it, fresh] = group_of.try_emplace(e, static_cast<int>(stepping.size()));
    if (fresh) stepping.push_back(e);
    for (const HalfEdge& h : f.half_edges) {
      const std::uint32_t a = vertex[h.from], b = vertex[h.to];
      if (a != b) segments.push_back({local(a), local(b), it->second});
    }
  }

  const ChainOverlay o = overlay_chains(std::move(points), segments, st.tol().position());
  for (std::size_t i = global.size(); i < o.points.size(); ++i) global.push_back(st.add_vertex({o.points[i], z}));

  for (std::size_t next = 0; next < written.size();) {
    const std::size_t f = written[next].first;
    std::vector<HalfEdge> cut;
    const std::vector<HalfEdge>& hs = st.faces[f].half_edges;
    for (std::size_t i = 0; i < hs.size(); ++i) {
      if (next == written.size() || written[next] != std::pair{f, i}) {
        cut.push_back(hs[i]);
        continue;
      }
      const std::vector<std::uint32_t>& chain = o.pieces[next++];
      for (std::size_t k = 0; k + 1 < chain.size(); ++k) cut.push_back({global[chain[k]], global[chain[k + 1]]});
    }
    st.faces[f].half_edges = std::move(cut);
  }

  std::map<int, int> face_of;  // group -> its horizontal face
  for (const OverlayCell& cell : o.cells) {
    auto [it, fresh] = face_of.try_emplace(cell.owner, 0);
    if (fresh) {
      const int e = stepping[cell.owner];
      const auto step = steps.find(st.edges[e].source);
      FaceGroup h;
      h.kind = FaceKind::Side;
      h.source_edge = st.edges[e].source_id;
      h.tag = step == steps.end() ? st.faces[st.edges[e].face].tag : step->second.step_tag;
      h.outward = {0.0, 0.0, cell.winding > 0 ? 1.0 : -1.0};
      h.origin = {0.0, 0.0, z};
      it->second = static_cast<int>(st.faces.size());
      st.faces.push_back(std::move(h));
    }
    // A soffit is seen from below: its cycles run the other way.
    std::vector<HalfEdge>& hs = st.faces[it->second].half_edges;
    const std::size_t m = cell.loop.size();
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint32_t a = global[cell.loop[k]], b = global[cell.loop[(k + 1) % m]];
      hs.push_back(cell.winding > 0 ? HalfEdge{a, b} : HalfEdge{b, a});
    }
  }
}

}  // namespace

void apply_horizontal_run(State& st, EventQueue& queue, const std::map<int, SourceStep>& steps) {
  const double z = st.height;
  const std::vector<std::vector<int>> loops = live_loops(st);
  std::vector<std::uint32_t> at(st.corners.size(), 0);
  for (const auto& loop : loops)
    for (int c : loop) at[c] = st.vertex_now(c);

  SweepOptions options;
  for (const auto& [s, step] : steps) options.max_height = std::max(options.max_height.value_or(0.0), std::abs(step.inward));
  options.ambiguity = st.options().ambiguity;
  Nested n{State(st.tol(), options), {}, {}, {}, *options.max_height};
  sweep_nested(n, st, loops, at, steps);
  const std::vector<std::uint32_t> vertex = flatten_vertices(n, st, z);

  // The faces below end on the cross-section.
  for (const auto& loop : loops)
    for (int c : loop) st.emit_top(st.corners[c].next_edge, at[c], at[st.corners[c].next]);

  // The planes above: each edge's line moved by its step, with the slope its
  // profile continues with. An edge that neither steps nor turns goes on.
  std::map<int, int> above;  // outer edge -> its plane above the run
  auto plane_above = [&](int j) {
    const int e = n.span_edge[j];
    auto [it, fresh] = above.try_emplace(e, e);
    if (!fresh) return it->second;
    const Edge old = st.edges[e];
    const std::string old_tag = st.faces[old.face].tag;
    const auto step = steps.find(old.source);
    const double k = step == steps.end() ? old.plane.k : step->second.slope;
    const std::string tag = step == steps.end() ? old_tag : step->second.tag;
    const double moved = n.st.edges[n.st.sources[j].edge].plane.k * n.reach;
    if (moved != 0.0 || k != old.plane.k || tag != old_tag) {
      const glm::dvec2 on_line = old.plane.n * (old.plane.offset_at(z) + moved);
      it->second = st.add_edge(on_line, z, old.dir, k, old.source, tag);
    }
    return it->second;
  };

  // The nested sweep's top is the new cross-section.
  for (const auto& loop : loops)
    for (int c : loop) st.corners[c].alive = false;
  std::vector<int> fresh(n.st.corners.size(), kNone);
  std::vector<int> made;
  for (int c = 0; c < static_cast<int>(n.st.corners.size()); ++c) {
    const Corner& k = n.st.corners[c];
    if (!k.alive) continue;
    const int prev = plane_above(n.st.edges[k.prev_edge].source);
    const int next = plane_above(n.st.edges[k.next_edge].source);
    fresh[c] = st.add_corner(prev, next, vertex[n.top[c]]);
    made.push_back(fresh[c]);
  }
  for (int c = 0; c < static_cast<int>(n.st.corners.size()); ++c) {
    const Corner& k = n.st.corners[c];
    if (!k.alive) continue;
    st.link(fresh[c], fresh[k.next]);
    const std::uint32_t a = vertex[n.top[c]], b = vertex[n.top[k.next]];
    if (a != b) st.faces[st.edges[st.corners[fresh[c]].next_edge].face].half_edges.push_back({a, b});
  }
  horizontal_faces(st, n, vertex, steps, z);
  for (int c : settle(st, made)) {
    queue.schedule(st, c);
    queue.schedule_edge_event(st, st.corners[c].prev);
  }
}

}  // namespace procex::engine
