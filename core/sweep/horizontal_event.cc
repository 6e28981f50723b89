#include "core/sweep/horizontal_event.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
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

// Nested vertices flattened onto the sweep plane at height z. Vertices that
// land on one point (within the clustering distance) are one vertex: a corner
// between edges that do not step stays where it is.
std::vector<std::uint32_t> flatten_vertices(const Nested& n, State& st, double z) {
  const double near = st.tol().position();
  std::map<std::pair<long long, long long>, std::vector<std::uint32_t>> grid;
  auto cell = [&](glm::dvec2 p) {
    return std::pair{static_cast<long long>(std::floor(p.x / near)), static_cast<long long>(std::floor(p.y / near))};
  };
  auto find = [&](glm::dvec2 p) -> std::optional<std::uint32_t> {
    const auto [cx, cy] = cell(p);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        auto it = grid.find({cx + dx, cy + dy});
        if (it == grid.end()) continue;
        for (std::uint32_t v : it->second)
          if (glm::length(glm::dvec2(st.vertices[v]) - p) <= near) return v;
      }
    return std::nullopt;
  };
  std::vector<std::uint32_t> out(n.st.vertices.size());
  for (std::size_t i = 0; i < n.base_vertex.size(); ++i) {
    out[i] = n.base_vertex[i];
    grid[cell(glm::dvec2(n.st.vertices[i]))].push_back(out[i]);
  }
  for (std::size_t i = n.base_vertex.size(); i < out.size(); ++i) {
    const glm::dvec2 p(n.st.vertices[i]);
    if (auto v = find(p)) {
      out[i] = *v;
      continue;
    }
    out[i] = st.add_vertex({p, z});
    grid[cell(p)].push_back(out[i]);
  }
  return out;
}

// Where an edge does not step, its nested face is a strip of no width on its
// own line, and everything meeting that line at z meets it at some vertex of
// that strip: the top of its face below, the bottom of its plane above and
// the horizontal faces of its neighbours. Each half-edge written at z along
// such a line is split at every vertex of the strip it passes, so faces meet
// vertex to vertex there (the strip itself is no face).
void split_along_lines(State& st, std::map<int, std::vector<std::uint32_t>> on_line,
                       const std::vector<std::size_t>& written_before) {
  std::map<std::uint32_t, std::vector<int>> lines_of;  // vertex -> the edges whose line it is on
  for (auto& [e, vs] : on_line) {
    std::sort(vs.begin(), vs.end());
    vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
    for (std::uint32_t v : vs) lines_of[v].push_back(e);
  }
  auto common_line = [&](std::uint32_t a, std::uint32_t b) -> int {
    const auto ia = lines_of.find(a), ib = lines_of.find(b);
    if (ia == lines_of.end() || ib == lines_of.end()) return kNone;
    for (int e : ia->second)
      if (std::find(ib->second.begin(), ib->second.end(), e) != ib->second.end()) return e;
    return kNone;
  };
  for (std::size_t f = 0; f < st.faces.size(); ++f) {
    std::vector<HalfEdge>& hs = st.faces[f].half_edges;
    const std::size_t from = f < written_before.size() ? written_before[f] : 0;
    std::vector<HalfEdge> split;
    for (std::size_t i = from; i < hs.size(); ++i) {
      const HalfEdge h = hs[i];
      const int e = common_line(h.from, h.to);
      if (e == kNone) {
        split.push_back(h);
        continue;
      }
      const glm::dvec2 d = st.edges[e].dir;
      auto along = [&](std::uint32_t v) { return glm::dot(glm::dvec2(st.vertices[v]), d); };
      const double ta = along(h.from), tb = along(h.to);
      std::vector<std::pair<double, std::uint32_t>> between;
      for (std::uint32_t v : on_line.at(e)) {
        const double t = (along(v) - ta) / (tb - ta);
        if (v != h.from && v != h.to && t > 0.0 && t < 1.0) between.push_back({t, v});
      }
      std::sort(between.begin(), between.end());
      std::uint32_t a = h.from;
      for (const auto& [t, v] : between) {
        split.push_back({a, v});
        a = v;
      }
      split.push_back({a, h.to});
    }
    hs.resize(from);
    hs.insert(hs.end(), split.begin(), split.end());
  }
}

}  // namespace

void apply_horizontal_run(State& st, EventQueue& queue, const std::map<int, SourceStep>& steps) {
  const double z = st.height;
  std::vector<std::size_t> written_before;
  for (const FaceGroup& f : st.faces) written_before.push_back(f.half_edges.size());
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

  // Flattened nested faces: an edge that steps makes a horizontal face; one
  // that does not only marks the vertices on its line (split_along_lines).
  std::map<int, int> ledge;  // outer edge -> its horizontal face
  std::map<int, std::vector<std::uint32_t>> on_line;  // outer edge that does not step -> vertices on its line
  auto slope_in_nested = [&](int j) { return n.st.edges[n.st.sources[j].edge].plane.k; };
  for (const FaceGroup& f : n.st.faces) {
    if (f.kind != FaceKind::Side) continue;
    const int j = f.source_edge;
    const int e = n.span_edge[j];
    const double k = slope_in_nested(j);
    if (k == 0.0) {
      std::vector<std::uint32_t>& vs = on_line[e];
      for (const HalfEdge& h : f.half_edges) vs.insert(vs.end(), {vertex[h.from], vertex[h.to]});
      continue;
    }
    auto [it, fresh] = ledge.try_emplace(e, 0);
    if (fresh) {
      const auto step = steps.find(st.edges[e].source);
      FaceGroup h;
      h.kind = FaceKind::Side;
      h.source_edge = st.edges[e].source_id;
      h.tag = step == steps.end() ? st.faces[st.edges[e].face].tag : step->second.step_tag;
      h.outward = {0.0, 0.0, k > 0.0 ? 1.0 : -1.0};
      h.origin = {0.0, 0.0, z};
      it->second = static_cast<int>(st.faces.size());
      st.faces.push_back(std::move(h));
    }
    for (const HalfEdge& h : f.half_edges) {
      const std::uint32_t a = vertex[h.from], b = vertex[h.to];
      if (a != b) st.faces[it->second].half_edges.push_back({a, b});
    }
  }

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
    const double moved = slope_in_nested(j) * n.reach;
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
  split_along_lines(st, std::move(on_line), written_before);
  for (int c : settle(st, made)) {
    queue.schedule(st, c);
    queue.schedule_edge_event(st, st.corners[c].prev);
  }
}

}  // namespace procex::engine
