#include "core/sweep/ambiguity.h"

namespace procex::engine {

bool ambiguous(const State& st, int c) { return st.corners[c].motion == Motion::Ambiguous; }

std::vector<int> resolve_ambiguity(State& st, int c) {
  std::vector<int> made;
  // Each step removes one span, so a loop of n corners settles in n steps.
  for (std::size_t guard = 0; guard <= st.corners.size() && ambiguous(st, c); ++guard) {
    const Corner k = st.corners[c];
    const double ka = st.edges[k.prev_edge].plane.k, kb = st.edges[k.next_edge].plane.k;
    // The plane leaning in less keeps more volume under it.
    const bool keep_prev = st.options().ambiguity == Ambiguity::MaximizeVolume ? ka <= kb : ka >= kb;
    st.corners[c].alive = false;
    if (keep_prev) {
      // The previous edge's plane runs on over the next edge's span, which ends here.
      const int t = k.next;
      const std::uint32_t vt = st.vertex_now(t);
      st.emit_top(k.next_edge, k.origin, vt);
      // The horizontal step now also bounds the kept face from below.
      st.faces[st.edges[k.prev_edge].face].half_edges.push_back({k.origin, vt});
      const int r = st.add_corner(k.prev_edge, st.corners[t].next_edge, vt);
      const int after = st.corners[t].next;
      st.corners[t].alive = false;
      st.link(k.prev, r);
      st.link(r, after);
      c = r;
    } else {
      const int s = k.prev;
      const std::uint32_t vs = st.vertex_now(s);
      st.emit_top(k.prev_edge, vs, k.origin);
      st.faces[st.edges[k.next_edge].face].half_edges.push_back({vs, k.origin});
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
