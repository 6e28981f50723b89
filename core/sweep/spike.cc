#include "core/sweep/spike.h"

#include <glm/geometric.hpp>

namespace procex::engine {

std::vector<int> close_spike(State& st, int c) {
  std::vector<int> made;
  // Each step removes at least one corner, so the loop's size bounds the steps.
  for (std::size_t guard = 0; guard <= st.corners.size(); ++guard) {
    const Corner tip = st.corners[c];
    const int s = tip.prev, t = tip.next;
    if (tip.motion != Motion::Ridge || s == t || st.corners[s].prev == t) break;
    const glm::dvec2 at = st.position(c, st.height);
    const glm::dvec2 along = st.edges[tip.next_edge].dir;
    const double ds = glm::dot(st.position(s, st.height) - at, along);
    const double dt = glm::dot(st.position(t, st.height) - at, along);
    const double same = st.tol().position();
    const bool fold_prev = ds <= dt + same;  // s lies on the next edge's span
    const bool fold_next = dt <= ds + same;  // t lies on the previous edge's span
    const int face_a = st.edges[tip.prev_edge].face, face_b = st.edges[tip.next_edge].face;
    const std::uint32_t vc = tip.origin;
    int before = s, after = t, prev_edge = tip.prev_edge, next_edge = tip.next_edge;
    std::uint32_t v = 0;
    if (fold_prev) {
      v = st.vertex_now(s);
      st.emit_top(tip.prev_edge, v, vc);
      before = st.corners[s].prev;
      prev_edge = st.corners[s].prev_edge;
      st.corners[s].alive = false;
    }
    if (fold_next) {
      if (fold_prev) {
        st.emit_trajectory(t, v);
      } else {
        v = st.vertex_now(t);
      }
      st.emit_top(tip.next_edge, vc, v);
      after = st.corners[t].next;
      next_edge = st.corners[t].next_edge;
      st.corners[t].alive = false;
    }
    // The folded span's ridge also bounds the part of the other face it lay on.
    if (fold_prev && !fold_next) st.faces[face_b].half_edges.push_back({v, vc});
    if (fold_next && !fold_prev) st.faces[face_a].half_edges.push_back({vc, v});
    st.corners[c].alive = false;
    const int n = st.add_corner(prev_edge, next_edge, v);
    st.link(before, n);
    st.link(n, after);
    made.push_back(n);
    c = n;
  }
  return made;
}

}  // namespace procex::engine
