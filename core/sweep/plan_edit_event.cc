#include "core/sweep/plan_edit_event.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <string>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/geom/predicates.h"
#include "core/geom/segment_intersections.h"
#include "core/sweep/anchor_event.h"
#include "core/sweep/driver.h"
#include "core/sweep/horizontal_event.h"
#include "core/sweep/settle.h"

namespace procex::engine {
namespace {

std::string named(const PlanEdit& e, std::size_t i) {
  return "plan edit '" + (e.name.empty() ? std::to_string(i) : e.name) + "'";
}

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void check_edit(const PlanEdit& e, const std::string& what, const std::vector<Profile>& profiles, double flat) {
  check_anchor(e.at, what);
  std::size_t want = 3;
  if (e.kind == PlanEdit::Kind::Forced) {
    if (e.shape.size() < 2) throw InputError(what + ": its shape needs at least 2 points");
    for (std::size_t i = 0; i < e.shape.size(); ++i) {
      if (!finite(e.shape[i])) throw InputError(what + ": shape point " + std::to_string(i) + " is not finite");
      if (i > 0 && e.shape[i] == e.shape[i - 1])
        throw InputError(what + ": shape points " + std::to_string(i - 1) + " and " + std::to_string(i) + " coincide");
    }
    if (e.shape.front().y != 0.0 || e.shape.back().y != 0.0)
      throw InputError(what + ": its shape must start and end on the edge (y = 0)");
    if (!(e.shape.back().x > e.shape.front().x))
      throw InputError(what + ": its shape must end further along the edge than it starts");
    want = e.shape.size() - 1;
  } else {
    if (!(std::isfinite(e.width) && e.width > 0.0)) throw InputError(what + ": width must be a positive number");
    if (!(std::isfinite(e.depth) && e.depth != 0.0)) throw InputError(what + ": depth must be a non-zero number");
    if (!std::isfinite(e.spread)) throw InputError(what + ": spread must be a finite number");
  }
  if (!std::isfinite(e.offset)) throw InputError(what + ": offset must be a finite number");
  if (e.edges.size() != want)
    throw InputError(what + ": it inserts " + std::to_string(want) + " edges but gives " +
                     std::to_string(e.edges.size()) + " edge specs");
  for (std::size_t j = 0; j < e.edges.size(); ++j) {
    const EdgeSpec& spec = e.edges[j];
    const std::string edge = what + ", inserted edge " + std::to_string(j);
    if (spec.profile < 0) {
      if (!(spec.angle_deg >= -90.0 && spec.angle_deg <= 90.0))
        throw InputError(edge + ": angle outside [-90, 90] degrees");
      continue;
    }
    if (spec.profile >= static_cast<int>(profiles.size()))
      throw InputError(edge + ": names profile " + std::to_string(spec.profile) + " but the footprint has " +
                       std::to_string(profiles.size()));
    const Profile& profile = profiles[static_cast<std::size_t>(spec.profile)];
    check_profile(profile);
    if (next_plane(profile, 0, flat).outward_step != 0.0)
      throw InputError(edge + ": profile '" + profile.name + "' starts with a horizontal segment; it must rise first");
  }
}

// A point of the step at the edit's height, in order along it.
struct StepPoint {
  std::uint32_t v;
  double u;       // along the old edge
  double y;       // outward from it
  bool on_line;   // on the old edge's line (its ends, touches, crossings)
  int edge;       // the inserted edge running from here to the next point
};

// Replaces half-edge `old` of face f by `by`; false if f has no such half-edge.
bool replace_half_edge(FaceGroup& f, HalfEdge old, std::initializer_list<HalfEdge> by) {
  auto it = std::find_if(f.half_edges.begin(), f.half_edges.end(),
                         [&](const HalfEdge& h) { return h.from == old.from && h.to == old.to; });
  if (it == f.half_edges.end()) return false;
  f.half_edges.erase(it);
  f.half_edges.insert(f.half_edges.end(), by);
  return true;
}

// The step's outputs at its height above the footprint: the old edge's face
// ends along the replaced part, and each lobe of the step off the old line is
// a horizontal face (facing down under a protrusion, up over a recess).
// Returns the lobes' faces.
std::vector<int> emit_lobes(State& st, int e, const std::vector<StepPoint>& pts, const std::string& tag) {
  std::vector<const StepPoint*> line;
  for (const StepPoint& p : pts)
    if (p.on_line) line.push_back(&p);
  std::sort(line.begin(), line.end(), [](const StepPoint* a, const StepPoint* b) { return a->u < b->u; });
  for (std::size_t k = 0; k + 1 < line.size(); ++k) st.emit_top(e, line[k]->v, line[k + 1]->v);

  std::vector<int> lobes;
  std::size_t start = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    if (!pts[i].on_line) continue;
    if (i - start > 1) {  // a run off the line
      FaceGroup f;
      f.kind = FaceKind::Side;
      f.source_edge = st.edges[e].source_id;
      f.tag = tag;
      f.outward = {0.0, 0.0, pts[start + 1].y > 0.0 ? -1.0 : 1.0};
      f.origin = st.vertices[pts[start].v];
      for (std::size_t m = start; m < i; ++m) f.half_edges.push_back({pts[m + 1].v, pts[m].v});
      const double lo = std::min(pts[start].u, pts[i].u), hi = std::max(pts[start].u, pts[i].u);
      for (std::size_t k = 0; k + 1 < line.size(); ++k)
        if (line[k]->u >= lo && line[k + 1]->u <= hi) f.half_edges.push_back({line[k]->v, line[k + 1]->v});
      lobes.push_back(static_cast<int>(st.faces.size()));
      st.faces.push_back(std::move(f));
    }
    start = i;
  }
  return lobes;
}

// Where the step's polyline (in world coordinates) would meet the live loops
// outside the part of span c it replaces, or itself: a loop that is not
// simple. Empty if it meets nothing. Meeting is within the clustering
// distance: a step that exactly touches the outline (as on a grid plan) is
// refused wherever rounding puts its corner, so a move of the plan cannot
// turn a refusal into a pinched solid.
std::string crossing(State& st, int c, const std::vector<glm::dvec2>& w) {
  const double z = st.height, near = st.tol().position();
  const std::size_t m = w.size() - 1;
  const int d = st.corners[c].next;
  // The host span's parts on either side of the step, then every other span.
  std::vector<std::pair<Segment2, std::int32_t>> others{{{st.position(c, z), w.front()}, -1},
                                                        {{w.back(), st.position(d, z)}, -1}};
  for (int k = 0; k < static_cast<int>(st.corners.size()); ++k)
    if (st.corners[k].alive && k != c)
      others.push_back({{st.position(k, z), st.position(st.corners[k].next, z)},
                        st.edges[st.corners[k].next_edge].source_id});
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t o = 0; o < others.size(); ++o) {
      if ((o == 0 && j == 0) || (o == 1 && j + 1 == m)) continue;  // they meet where the step starts or ends
      const Segment2& s = others[o].first;
      if (segments_meet({w[j], w[j + 1]}, s, near))
        return o < 2 ? "runs back across the edge it stands on"
                     : "crosses the building's outline (edge " + std::to_string(others[o].second) + ")";
    }
    for (std::size_t k = j + 2; k < m; ++k)
      if (segments_meet({w[j], w[j + 1]}, {w[k], w[k + 1]}, near)) return "crosses itself";
  }
  return {};
}

}  // namespace

PlanEditEvents::PlanEditEvents(const State& st, const std::vector<Profile>& profiles) : profiles_(&profiles) {
  const std::vector<PlanEdit>& edits = st.options().plan_edits;
  // Only the footprint's own edges can be selected: the sources so far.
  const int footprint_sources = static_cast<int>(st.sources.size());
  for (std::size_t i = 0; i < edits.size(); ++i) {
    const PlanEdit& e = edits[i];
    const std::string what = named(e, i);
    check_edit(e, what, profiles, st.tol().height());
    bool any = false;
    for (int s = 0; s < footprint_sources; ++s) {
      if (!selects(e.at, st.sources[s])) continue;
      any = true;
      requests_.push_back({i, s, e.at.height});
      ResolvedAnchor r;
      r.name = e.name;
      r.anchor = i;
      r.edge_id = st.sources[s].id;
      r.absence = Absence::AboveSweep;
      r.reason = "the sweep ends below its height";
      out_.push_back(std::move(r));
    }
    if (!any) throw InputError(what + " selects no edge of the footprint");
  }
  order_.resize(requests_.size());
  std::iota(order_.begin(), order_.end(), 0);
  std::stable_sort(order_.begin(), order_.end(),
                   [&](std::size_t x, std::size_t y) { return requests_[x].height < requests_[y].height; });
}

double PlanEditEvents::next_height() const { return requests_[order_[next_]].height; }

std::vector<ResolvedAnchor> PlanEditEvents::finish() {
  next_ = order_.size();
  return std::move(out_);
}

void PlanEditEvents::apply_next(State& st, EventQueue& queue, ProfileEvents& profile_events) {
  // Every request at this height is spliced in before any step grows, so the
  // footprint (or the cross-section) takes them all as they were placed.
  const double z = next_height();
  Batch batch;
  while (!empty() && next_height() <= z + st.tol().height()) {
    const std::size_t i = order_[next_++];
    splice(st, requests_[i], out_[i], batch);
  }
  finish_batch(st, queue, profile_events, batch);
}

void PlanEditEvents::splice(State& st, const Request& q, ResolvedAnchor& r, Batch& batch) {
  const PlanEdit& edit = st.options().plan_edits[q.edit];
  const double z = st.height;
  const std::optional<EdgePoint> hit = locate(st, q.source, edit.at.plan, z, r, edit.offset);
  if (!hit) return;
  const int e = st.sources[q.source].edge;
  const Edge edge = st.edges[e];
  const glm::dvec2 out_dir = -edge.plane.n;
  const bool natural = edit.kind == PlanEdit::Kind::Natural;

  // A natural step starts as a sliver that the horizontal run below grows.
  std::vector<glm::dvec2> shape = edit.shape;
  double sliver = 0.0;
  if (natural) {
    sliver = std::copysign(std::min(0.25 * std::abs(edit.depth), 1e3 * st.tol().position()), edit.depth);
    const double w = 0.5 * edit.width;
    shape = {{-w, 0.0}, {-w, sliver}, {w, sliver}, {w, 0.0}};
  }

  // The step must lie inside the span that holds the anchor.
  const int c = hit->span;
  const int d = st.corners[c].next;
  const double ua = glm::dot(st.position(c, z), edge.dir), ub = glm::dot(st.position(d, z), edge.dir);
  const double u0 = hit->u + shape.front().x, u1 = hit->u + shape.back().x;
  const double room = 4.0 * st.tol().position();
  if (u0 < ua + room || u1 > ub - room) {
    r.absence = Absence::NoRoom;
    r.reason = "it does not fit on edge " + std::to_string(st.sources[q.source].id) + " at height " +
               std::to_string(z) + ": the step spans " + std::to_string(u1 - u0) + " but the face is " +
               std::to_string(ub - ua) + " long there and the step reaches past its end";
    return;
  }

  const double near = st.tol().position();
  auto world = [&](glm::dvec2 local) { return hit->point + local.x * edge.dir + local.y * out_dir; };
  std::vector<glm::dvec2> corners;  // the shape's points where they will stand
  for (glm::dvec2 p : shape) corners.push_back(world(p));
  for (std::size_t j = 0; j + 1 < corners.size(); ++j)
    if (glm::length(corners[j + 1] - corners[j]) <= near) {
      r.absence = Absence::TooShort;
      r.reason = "its segment " + std::to_string(j) + " is shorter than the sweep's resolution";
      return;
    }

  if (const std::string where = crossing(st, c, corners); !where.empty()) {
    r.absence = Absence::Crossing;
    r.reason = "its shape " + where + " at height " + std::to_string(z) +
               (natural ? "" : "; a natural step grows round what it meets");
    return;
  }

  // The step's points (with a vertex where it crosses the old line) and its new edges.
  std::vector<StepPoint> pts;
  auto add_point = [&](glm::dvec2 local, int edge_index) {
    const glm::dvec2 p = world(local);
    const bool on_line = std::abs(local.y) <= near;
    pts.push_back({st.add_vertex({p, z}), hit->u + local.x, on_line ? 0.0 : local.y, on_line, edge_index});
  };
  const int first_edge = static_cast<int>(st.edges.size());
  for (std::size_t j = 0; j + 1 < shape.size(); ++j) {
    const glm::dvec2 a = shape[j], b = shape[j + 1];
    add_point(a, static_cast<int>(j));
    if ((a.y > near && b.y < -near) || (a.y < -near && b.y > near)) add_point(a + (b - a) * (a.y / (a.y - b.y)), static_cast<int>(j));
  }
  add_point(shape.back(), kNone);
  pts.back().on_line = true;
  pts.front().on_line = true;

  std::vector<int> new_edges, new_sources;
  for (std::size_t j = 0; j + 1 < shape.size(); ++j) {
    const glm::dvec2 a = corners[j], b = corners[j + 1];
    const int s = static_cast<int>(st.sources.size());
    const FirstPlane first = add_source(st, *profiles_, edit.edges[j], z);
    st.sources[s].start = a;
    st.sources[s].end = b;
    new_sources.push_back(s);
    new_edges.push_back(st.add_edge(a, z, glm::normalize(b - a), first.slope, s, first.tag));
  }
  for (auto& p : pts)
    if (p.edge != kNone) p.edge = first_edge + p.edge;

  // Corners where the step leaves the old edge, turns, and rejoins it.
  std::vector<int> made;
  int prev_corner = c;
  int prev_edge = e;
  for (const StepPoint& p : pts) {
    const int next_edge = p.edge == kNone ? e : p.edge;
    if (next_edge == prev_edge) continue;  // a crossing of the old line, not a corner
    const int k = st.add_corner(prev_edge, next_edge, p.v);
    st.link(prev_corner, k);
    made.push_back(k);
    prev_corner = k;
    prev_edge = next_edge;
  }
  st.link(prev_corner, d);
  for (std::size_t m = 0; m + 1 < pts.size(); ++m) st.faces[st.edges[pts[m].edge].face].half_edges.push_back({pts[m].v, pts[m + 1].v});

  std::vector<int> lobes;
  if (z <= st.tol().height()) {
    // On the footprint the step changes the footprint: the old edge's bottom
    // and the base give way to the step.
    const std::uint32_t oc = st.corners[c].origin, od = st.corners[d].origin;
    const std::uint32_t va = pts.front().v, vb = pts.back().v;
    if (!replace_half_edge(st.faces[edge.face], {oc, od}, {{oc, va}, {vb, od}}) ||
        !replace_half_edge(st.faces[st.base_face], {od, oc}, {{od, vb}, {va, oc}}))
      throw SweepError("sweep: " + named(edit, q.edit) + " cannot be inserted into the footprint at edge " +
                           std::to_string(st.sources[q.source].id),
                       z, {st.sources[q.source].id});
    for (std::size_t m = 0; m + 1 < pts.size(); ++m) st.faces[st.base_face].half_edges.push_back({pts[m + 1].v, pts[m].v});
  } else {
    lobes = emit_lobes(st, e, pts, edit.tag);
  }

  r.present = true;
  r.absence = Absence::None;
  r.reason.clear();
  r.frame.origin = {hit->point, z};
  r.frame.along = {edge.dir, 0.0};
  r.frame.normal = st.faces[edge.face].outward;
  r.frame.up = glm::cross(r.frame.normal, r.frame.along);
  r.span_from = {st.position(c, z), z};
  r.span_to = {st.position(d, z), z};

  batch.new_sources.insert(batch.new_sources.end(), new_sources.begin(), new_sources.end());
  batch.new_edges.insert(batch.new_edges.end(), new_edges.begin(), new_edges.end());
  if (!natural) {
    batch.made.insert(batch.made.end(), made.begin(), made.end());
    return;
  }
  // The sliver grows to the step's depth in the batch's horizontal run: the
  // front moves out (or in), the sides spread.
  const double out = edit.depth - sliver;
  const double side = edit.depth > 0.0 ? edit.spread : -edit.spread;
  for (std::size_t j = 0; j < new_sources.size(); ++j) {
    const int s = new_sources[j];
    const Edge& ne = st.edges[st.sources[s].edge];
    batch.steps[s] = {j == 1 ? -out : -side, edit.tag, ne.plane.k, st.faces[ne.face].tag};
  }
  if (!lobes.empty()) batch.slivers.push_back({lobes.front(), {pts[1].v, pts[2].v}});
}

void PlanEditEvents::finish_batch(State& st, EventQueue& queue, ProfileEvents& profile_events, Batch& batch) {
  const double z = st.height;
  if (!batch.steps.empty()) {
    // One nested sweep grows every natural step at this height; it remakes
    // and schedules every corner, the forced steps' too.
    const std::size_t before = st.faces.size();
    apply_horizontal_run(st, queue, profile_events, batch.steps);
    // At the footprint the grown floors (or the recesses' ceilings) are part
    // of the base; above it each sliver joins the floor grown from its front.
    for (std::size_t f = before; f < st.faces.size(); ++f) {
      auto& hs = st.faces[f].half_edges;
      // Only the horizontal faces (the planes above the run, a jog's too, lean).
      if (std::abs(st.faces[f].outward.z) != 1.0) continue;
      if (z <= st.tol().height()) {
        auto& base = st.faces[st.base_face].half_edges;
        base.insert(base.end(), hs.begin(), hs.end());
        hs.clear();
        continue;
      }
      for (const Sliver& sl : batch.slivers) {
        const bool from_front = std::any_of(hs.begin(), hs.end(), [&](const HalfEdge& h) {
          return h.from == sl.front.from && h.to == sl.front.to;
        });
        if (!from_front) continue;
        auto& sliver_face = st.faces[sl.face].half_edges;
        hs.insert(hs.end(), sliver_face.begin(), sliver_face.end());
        sliver_face.clear();
      }
    }
  } else {
    std::vector<char> fresh(st.corners.size(), 0);
    std::vector<int> live;
    settle(st, batch.made, live);
    for (int k : live) {
      queue.schedule(st, k);
      queue.schedule_edge_event(st, st.corners[k].prev);
      fresh[k] = 1;
    }
    // Corners elsewhere may cut into the new edges.
    for (int k = 0; k < static_cast<int>(fresh.size()); ++k)
      if (st.corners[k].alive && !fresh[k]) queue.schedule_splits(st, k, batch.new_edges);
  }
  for (int s : batch.new_sources) profile_events.schedule(st, s);
}

}  // namespace procex::engine
