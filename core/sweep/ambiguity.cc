#include "core/sweep/ambiguity.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace procex::engine {

bool ambiguous(const State& st, int c) { return st.corners[c].motion == Motion::Ambiguous; }

namespace {

// Emits from -> to in a face, passing through every vertex of `line` that lies
// strictly between them: the steps of one resolution share a line, and faces
// must meet vertex to vertex along it.
void emit_along(State& st, int face, std::uint32_t from, std::uint32_t to, const std::vector<std::uint32_t>& line) {
  if (from == to) return;
  const glm::dvec3 a = st.vertices[from], d = st.vertices[to] - a;
  const double len2 = glm::dot(d, d);
  std::vector<std::pair<double, std::uint32_t>> between;
  for (std::uint32_t v : line) {
    if (v == from || v == to) continue;
    const double t = glm::dot(st.vertices[v] - a, d) / len2;
    if (t > 0.0 && t < 1.0) between.push_back({t, v});
  }
  std::sort(between.begin(), between.end());
  auto& out = st.faces[face].half_edges;
  for (const auto& [t, v] : between) {
    if (v == from) continue;
    out.push_back({from, v});
    from = v;
  }
  out.push_back({from, to});
}

}  // namespace

std::vector<int> resolve_ambiguity(State& st, int c, double straight) {
  std::vector<int> made;
  std::vector<std::uint32_t> line{st.corners[c].origin};
  // Each step removes one span, so a loop of n corners settles in n steps.
  for (std::size_t guard = 0; guard <= st.corners.size() && ambiguous(st, c); ++guard) {
    const Corner k = st.corners[c];
    const int face_a = st.edges[k.prev_edge].face, face_b = st.edges[k.next_edge].face;
    const double ka = st.edges[k.prev_edge].plane.k, kb = st.edges[k.next_edge].plane.k;
    const Plane& pa = st.edges[k.prev_edge].plane;
    const Plane& pb = st.edges[k.next_edge].plane;
    // Where the corner lies off its neighbours' line by more than `straight`,
    // the lines cross there, and the corner (too fast to follow, motion_of)
    // runs along them one way: the plane of the span it does not run into
    // runs on over the other, which ends here (a wall beside a roof at 72
    // degrees on a line bent by 3.7e-7 rad, its corner at 8e6 m per m,
    // generated_random_polygons_scan_1607). On a line straight up to that,
    // the plane leaning in less keeps more volume under it.
    const glm::dvec2 at = st.position(c, st.height);
    const double shorter = std::min(glm::distance(st.position(k.prev, st.height), at),
                                    glm::distance(at, st.position(k.next, st.height)));
    const bool keep_prev = std::abs(cross(pa.n, pb.n)) * shorter > straight
                               ? glm::dot(crossing_velocity(pa, pb), st.edges[k.next_edge].dir) > 0.0
                               : st.options().ambiguity == Ambiguity::MaximizeVolume ? ka <= kb : ka >= kb;
    st.corners[c].alive = false;
    if (keep_prev) {
      // The previous edge's plane runs on over the next edge's span, which ends
      // here; the horizontal step is the top of one face and the foot of the other.
      const int t = k.next;
      const std::uint32_t vt = st.vertex_now(t);
      line.push_back(vt);
      emit_along(st, face_b, vt, k.origin, line);
      emit_along(st, face_a, k.origin, vt, line);
      st.edges[k.next_edge].heir = k.prev_edge;
      const int r = st.add_corner(k.prev_edge, st.corners[t].next_edge, vt);
      const int after = st.corners[t].next;
      st.corners[t].alive = false;
      st.link(k.prev, r);
      st.link(r, after);
      c = r;
    } else {
      const int s = k.prev;
      const std::uint32_t vs = st.vertex_now(s);
      line.push_back(vs);
      emit_along(st, face_a, k.origin, vs, line);
      emit_along(st, face_b, vs, k.origin, line);
      st.edges[k.prev_edge].heir = k.next_edge;
      const int r = st.add_corner(st.corners[s].prev_edge, k.next_edge, vs);
      const int before = st.corners[s].prev;
      st.corners[s].alive = false;
      st.link(before, r);
      st.link(r, k.next);
      c = r;
    }
    made.push_back(c);
  }
  return made;
}

}  // namespace procex::engine
