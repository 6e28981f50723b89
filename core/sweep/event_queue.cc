#include "core/sweep/event_queue.h"

namespace procex::engine {

void EventQueue::push(State& st, const Candidate& c) {
  // A meeting point below the sweep plane means the planes diverge from here.
  if (c.z < st.height - st.tol().height()) return;
  Candidate k = c;
  if (k.z < st.height) k.z = st.height;
  heap_.push(k);
}

void EventQueue::schedule_edge_event(State& st, int c) {
  const Corner& k = st.corners[c];
  const int n = k.next;
  if (n == kNone || n == c || k.next_edge == st.corners[n].next_edge) return;
  const Plane& shared = st.edges[k.next_edge].plane;
  if (auto p = meet3(st.plane_before(c), shared, st.plane_after(n), Tolerances::singular_det)) {
    push(st, {p->z, {p->x, p->y}, c, n, kNone});
  }
}

void EventQueue::schedule(State& st, int c) {
  schedule_edge_event(st, c);
  const Corner& k = st.corners[c];
  if (!st.any_outward && !k.guide && !st.reflex(c)) return;
  const Plane& a = st.plane_before(c);
  const Plane& b = st.edges[k.next_edge].plane;
  for (int e = 0; e < static_cast<int>(st.edges.size()); ++e) {
    if (e == k.prev_edge || e == k.next_edge || st.spans(e).empty()) continue;
    if (auto p = meet3(a, b, st.edges[e].plane, Tolerances::singular_det)) {
      push(st, {p->z, {p->x, p->y}, c, kNone, e});
    }
  }
}

std::vector<Candidate> EventQueue::pop_cluster(double height_tolerance) {
  std::vector<Candidate> out;
  const double top = heap_.top().z;
  while (!heap_.empty() && heap_.top().z <= top + height_tolerance) {
    out.push_back(heap_.top());
    heap_.pop();
  }
  return out;
}

}  // namespace procex::engine
