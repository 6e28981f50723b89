#include "core/sweep/event_queue.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

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
  if (n == kNone || n == c) return;
  // The span between c and n runs along the edge's direction; it closes when
  // its length along that direction reaches zero.
  const glm::dvec2 d = st.edges[k.next_edge].dir;
  const double z = st.height;
  const double length = glm::dot(st.position(n, z) - st.position(c, z), d);
  const double rate = glm::dot(st.corners[n].velocity - k.velocity, d);
  if (!(rate < 0.0)) return;
  const double at = z - length / rate;
  // Two corners made at one collision meet there because of it.
  if (k.origin == st.corners[n].origin && at <= z + st.tol().height()) return;
  push(st, {at, 0.5 * (st.position(c, at) + st.position(n, at)), c, n, kNone});
}

void EventQueue::schedule(State& st, int c, const std::vector<int>& resolved) {
  schedule_edge_event(st, c);
  std::vector<int> all;
  for (int e = 0; e < static_cast<int>(st.edges.size()); ++e)
    if (!st.spans(e).empty()) all.push_back(e);
  schedule_splits(st, c, all, resolved);
}

void EventQueue::schedule_splits(State& st, int c, const std::vector<int>& edges, const std::vector<int>& resolved) {
  const Corner& k = st.corners[c];
  if (!st.any_outward && k.motion == Motion::Regular && !st.reflex(c)) return;
  const double z = st.height;
  const glm::dvec2 p = st.position(c, z);
  for (int e : edges) {
    if (e == k.prev_edge || e == k.next_edge) continue;
    // Signed distance from the edge's line changes at `rate`: a corner inside
    // meets it when the distance falls to zero, a corner of another polygon
    // growing towards it (from outside) when it rises to zero.
    const Plane& pl = st.edges[e].plane;
    const double rate = glm::dot(pl.n, k.velocity) - pl.k;
    if (rate == 0.0 || (rate > 0.0 && !st.any_outward)) continue;
    const double at = z - pl.signed_distance(p, z) / rate;
    // A corner made by a collision with this edge meets it there because of it.
    if (at <= z + st.tol().height() && std::find(resolved.begin(), resolved.end(), e) != resolved.end()) continue;
    push(st, {at, st.position(c, at), c, kNone, e});
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
