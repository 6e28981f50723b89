#include "core/sweep/profile_event.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/geom/error.h"
#include "core/sweep/horizontal_event.h"
#include "core/sweep/settle.h"

namespace procex::engine {

double segment_slope(const Profile& profile, std::size_t segment) {
  const glm::dvec2 d = profile.points[segment + 1] - profile.points[segment];
  // Outward offset growing with height leans out: a negative inward slope.
  const double k = -d.x / d.y;
  return std::clamp(k, -Tolerances::max_slope, Tolerances::max_slope);
}

NextPlane next_plane(const Profile& profile, std::size_t point, double flat) {
  auto horizontal = [&](std::size_t seg) { return profile.points[seg + 1].y - profile.points[seg].y <= flat; };
  double step = 0.0;
  std::size_t seg = point;
  while (seg < profile.segments() && horizontal(seg)) {
    step += profile.points[seg + 1].x - profile.points[seg].x;
    ++seg;
  }
  if (seg < profile.segments()) return {seg, seg, step};
  // Above its last point an edge carries on with the profile's last slope.
  std::size_t last = profile.segments() - 1;
  while (last > 0 && horizontal(last)) --last;
  return {last, profile.points.size() - 1, step};
}

void ProfileEvents::schedule(const State& st, int s) {
  const Source& src = st.sources[s];
  if (!src.profile) return;
  const std::size_t next = src.point + 1;
  if (next >= src.profile->points.size()) return;
  heap_.push({src.base + src.profile->points[next].y, s});
}

std::vector<int> ProfileEvents::pop(double tolerance) {
  std::vector<int> out;
  const double top = heap_.top().first;
  while (!heap_.empty() && heap_.top().first <= top + tolerance) {
    out.push_back(heap_.top().second);
    heap_.pop();
  }
  std::sort(out.begin(), out.end());
  return out;
}

void apply_profile_events(State& st, EventQueue& queue, ProfileEvents& events, const std::vector<int>& sources) {
  const double z = st.height;
  std::map<int, SourceStep> steps;
  bool sideways = false;
  for (int s : sources) {
    Source& src = st.sources[s];
    const Profile& profile = *src.profile;
    auto tag = [&](std::size_t segment) { return profile.tags.empty() ? std::string() : profile.tags[segment]; };
    const NextPlane next = next_plane(profile, src.point + 1, st.tol().height());
    steps[s] = {-next.outward_step, next.outward_step != 0.0 ? tag(src.point + 1) : std::string(),
                segment_slope(profile, next.segment), tag(next.segment)};
    sideways = sideways || next.outward_step != 0.0;
    src.point = next.point;
    events.schedule(st, s);
  }
  if (sideways) {
    apply_horizontal_run(st, queue, events, steps);
    return;
  }
  // New planes through each changing edge's current line.
  std::vector<int> replaced(st.edges.size(), kNone);
  for (const auto& [s, step] : steps) {
    const int old = st.sources[s].edge;
    const Edge& e = st.edges[old];
    if (step.slope == e.plane.k && step.tag == st.faces[e.face].tag) continue;  // the same plane goes on
    const glm::dvec2 on_line = e.plane.n * e.plane.offset_at(z);
    replaced[old] = st.add_edge(on_line, z, e.dir, step.slope, s, step.tag);
  }
  replaced.resize(st.edges.size(), kNone);
  auto now = [&](int e) { return replaced[e] == kNone ? e : replaced[e]; };

  // Every corner on a changing edge ends here and starts again on the new planes.
  std::vector<int> old_corners;
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c) {
    const Corner& k = st.corners[c];
    if (k.alive && (replaced[k.prev_edge] != kNone || replaced[k.next_edge] != kNone)) old_corners.push_back(c);
  }
  std::vector<int> fresh(st.corners.size(), kNone);
  std::vector<std::uint32_t> at(st.corners.size(), 0);
  for (int c : old_corners) at[c] = st.vertex_now(c);
  for (int c : old_corners) {
    const Corner k = st.corners[c];
    fresh[c] = st.add_corner(now(k.prev_edge), now(k.next_edge), at[c]);
  }
  fresh.resize(st.corners.size(), kNone);
  for (int c : old_corners) {
    const Corner k = st.corners[c];
    const int n = fresh[c];
    const int prev = fresh[k.prev] == kNone ? k.prev : fresh[k.prev];
    const int next = fresh[k.next] == kNone ? k.next : fresh[k.next];
    st.link(prev, n);
    st.link(n, next);
    // The old plane's face ends on this span; the new plane's face starts on it.
    if (replaced[k.next_edge] != kNone) {
      const std::uint32_t v_next = at[k.next];
      st.emit_top(k.next_edge, at[c], v_next);
      st.faces[st.edges[now(k.next_edge)].face].half_edges.push_back({at[c], v_next});
    }
  }
  std::vector<int> made;
  for (int c : old_corners) {
    st.corners[c].alive = false;
    made.push_back(fresh[c]);
  }
  std::vector<int> live;
  settle(st, made, live);
  std::vector<char> scheduled(st.corners.size(), 0);
  for (int c : live) {
    queue.schedule(st, c);
    queue.schedule_edge_event(st, st.corners[c].prev);
    scheduled[c] = 1;
  }
  // Corners elsewhere may cut into the new planes.
  std::vector<int> planes;
  for (int e : replaced)
    if (e != kNone) planes.push_back(e);
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c)
    if (st.corners[c].alive && !scheduled[c]) queue.schedule_splits(st, c, planes);
}

}  // namespace procex::engine
