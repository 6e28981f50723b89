#include "core/sweep/cap_event.h"

namespace procex::engine {

void cap_at(State& st, double h) {
  st.height = h;
  FaceGroup cap;
  cap.kind = FaceKind::Cap;
  cap.outward = {0.0, 0.0, 1.0};
  cap.origin = {0.0, 0.0, h};
  std::vector<std::uint32_t> vertex_of(st.corners.size(), 0);
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c)
    if (st.corners[c].alive) vertex_of[c] = st.vertex_now(c);
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c) {
    if (!st.corners[c].alive) continue;
    const int t = st.corners[c].next;
    // The loops run counter-clockwise around the solid seen from above.
    cap.half_edges.push_back({vertex_of[c], vertex_of[t]});
    st.emit_top(st.corners[c].next_edge, vertex_of[c], vertex_of[t]);
  }
  for (auto& c : st.corners) c.alive = false;
  st.faces.push_back(std::move(cap));
}

}  // namespace procex::engine
