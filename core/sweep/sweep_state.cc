#include "core/sweep/sweep_state.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <glm/geometric.hpp>

#include "core/sweep/spares.h"

namespace procex::engine {

// A finished State's arrays, emptied, their storage kept.
struct StateArrays {
  std::vector<Source> sources;
  std::vector<Edge> edges;
  std::vector<Corner> corners;
  std::vector<glm::dvec3> vertices;
};

State::State(const Tolerances& tol, const SweepOptions& options, Budget* budget)
    : plan_position{glm::dvec2(0.0), tol.position()},
      tol_(tol),
      options_(options),
      budget_(budget),
      arrays_(Spares<StateArrays>::take()) {
  sources.swap(arrays_->sources);
  edges.swap(arrays_->edges);
  corners.swap(arrays_->corners);
  vertices.swap(arrays_->vertices);
}

State::State(State&&) noexcept = default;
State& State::operator=(State&&) noexcept = default;

State::~State() {
  if (!arrays_) return;  // moved from: its arrays went with the move
  const std::size_t made = corners.size();
  sources.clear();
  edges.clear();
  corners.clear();
  vertices.clear();
  arrays_->sources.swap(sources);
  arrays_->edges.swap(edges);
  arrays_->corners.swap(corners);
  arrays_->vertices.swap(vertices);
  Spares<StateArrays>::give(std::move(arrays_), made);
}

int State::add_edge(glm::dvec2 point, double z0, glm::dvec2 dir, double k, int source, const std::string& tag,
                    int face) {
  Edge e;
  e.plane = Plane::through(point, z0, dir, k);
  e.dir = dir;
  e.source = source;
  e.source_id = sources[source].id;
  if (face < 0) {
    face = static_cast<int>(faces.size());
    FaceGroup f;
    f.kind = FaceKind::Side;
    f.source_edge = e.source_id;
    f.tag = tag;
    // The face's gradient (n, -k) points inward and down; outward is its opposite.
    f.outward = glm::normalize(glm::dvec3{-e.plane.n.x, -e.plane.n.y, k});
    f.origin = glm::dvec3{point, z0};
    // Room for a quad with a trajectory or two more: one allocation per face, not three or four.
    f.half_edges.reserve(6);
    faces.push_back(std::move(f));
  }
  e.face = face;
  if (k < 0.0) any_outward = true;
  edges.push_back(std::move(e));
  sources[source].edge = static_cast<int>(edges.size()) - 1;
  return static_cast<int>(edges.size()) - 1;
}

int State::add_corner(int prev_edge, int next_edge, std::uint32_t origin) {
  Corner c;
  c.prev_edge = prev_edge;
  c.next_edge = next_edge;
  c.origin = origin;
  c.base = glm::dvec2(vertices[origin]);
  c.base_z = vertices[origin].z;
  std::tie(c.motion, c.velocity) = motion_of(prev_edge, next_edge);
  if (budget_) budget_->add_corner(height);
  const int id = static_cast<int>(corners.size());
  corners.push_back(c);
  Edge& e = edges[next_edge];
  (e.last_span == kNone ? e.first_span : corners[e.last_span].next_span) = id;
  e.last_span = id;
  ++e.listed_spans;
  return id;
}

std::pair<Motion, glm::dvec2> State::motion_of(int prev_edge, int next_edge) const {
  const Plane& a = edges[prev_edge].plane;
  const Plane& b = edges[next_edge].plane;
  const bool same_direction = glm::dot(edges[prev_edge].dir, edges[next_edge].dir) > 0.0;
  const double det = cross(a.n, b.n);
  Motion motion = Motion::Regular;
  glm::dvec2 velocity{0.0};
  if (std::abs(det) > Tolerances::parallel_sin) {
    velocity = crossing_velocity(a, b);
    if (glm::length(velocity) > Tolerances::max_speed * (1.0 + std::abs(a.k) + std::abs(b.k)))
      motion = same_direction ? Motion::Ambiguous : Motion::Ridge;
  } else if (!same_direction) {
    motion = Motion::Ridge;
  } else if (std::abs(a.k - b.k) <= Tolerances::same_slope * (1.0 + std::abs(a.k))) {
    motion = Motion::Parallel;
    velocity = a.k * a.n;
  } else {
    motion = Motion::Ambiguous;
  }
  if (motion == Motion::Ambiguous || motion == Motion::Ridge) velocity = glm::dvec2(0.0);
  return {motion, velocity};
}

std::uint32_t State::add_vertex(glm::dvec3 p) {
  if (budget_) budget_->add_vertex(height);
  vertices.push_back(p);
  return static_cast<std::uint32_t>(vertices.size() - 1);
}

State::LevelSlot& State::level_slot(std::int64_t x, std::int64_t y) {
  // Unsigned arithmetic: far cells wrap instead of overflowing.
  const auto hash = static_cast<std::uint64_t>(x) * 73856093ULL ^ static_cast<std::uint64_t>(y) * 19349663ULL;
  const std::size_t mask = level_slots_.size() - 1;
  for (std::size_t i = (hash ^ hash >> 29) & mask;; i = (i + 1) & mask) {
    LevelSlot& s = level_slots_[i];
    if (s.level != level_ || (s.x == x && s.y == y)) return s;
  }
}

std::uint32_t State::vertex_at(glm::dvec2 p, double z) {
  if (std::abs(height - level_height_) > tol_.height()) {
    ++level_;
    level_height_ = height;
    level_used_ = 0;
  }
  const double cell = tol_.position();
  const auto gx = static_cast<std::int64_t>(std::floor(p.x / cell));
  const auto gy = static_cast<std::int64_t>(std::floor(p.y / cell));
  for (std::int64_t dx = -1; dx <= 1; ++dx)
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      const LevelSlot& s = level_slot(gx + dx, gy + dy);
      if (s.level != level_) continue;
      const glm::dvec3& q = vertices[s.v];
      if (std::abs(q.z - z) <= tol_.height() && glm::length(glm::dvec2(q) - p) <= cell) return s.v;
    }
  const std::uint32_t v = add_vertex({p, z});
  // A cell keeps the first vertex made in it.
  if (level_slot(gx, gy).level == level_) return v;
  if (2 * (level_used_ + 1) > level_slots_.size()) {
    std::vector<LevelSlot> old(2 * level_slots_.size());
    old.swap(level_slots_);
    for (const LevelSlot& s : old)
      if (s.level == level_) level_slot(s.x, s.y) = s;
  }
  level_slot(gx, gy) = {level_, gx, gy, v};
  ++level_used_;
  return v;
}

bool State::reflex(int c) const {
  const Corner& k = corners[c];
  return cross(edges[k.prev_edge].dir, edges[k.next_edge].dir) <= Tolerances::parallel_sin;
}

// The span runs along the edge's direction; it closes when its length along
// that direction reaches zero.
double State::span_rate(int c) const {
  const Corner& k = corners[c];
  return glm::dot(corners[k.next].velocity - k.velocity, edges[k.next_edge].dir);
}

double State::span_closes_at(int c, double floor) const {
  const Corner& k = corners[c];
  const int n = k.next;
  const double length = glm::dot(position(n, height) - position(c, height), edges[k.next_edge].dir);
  const double rate = span_rate(c);
  const double at = rate < 0.0 ? height - length / rate : NAN;
  if (!(at >= floor - tol_.height())) return NAN;
  if (k.origin == corners[n].origin && at <= floor + tol_.height()) return NAN;
  return at;
}

double State::meeting_slack(int a, int b, int c, std::span<const int> ends) const {
  for (int k : ends)
    if (corners[k].motion != Motion::Regular) return 0.0;
  return tol_.meeting_slack(meeting_condition(edges[a].plane, edges[b].plane, edges[c].plane));
}

void State::emit_trajectory(int c, std::uint32_t v) {
  const Corner& k = corners[c];
  if (v == k.origin) return;
  // Seen from outside, the face of prev_edge has this corner on its right side
  // (going up), the face of next_edge has it on its left side (going down).
  faces[edges[k.prev_edge].face].half_edges.push_back({k.origin, v});
  faces[edges[k.next_edge].face].half_edges.push_back({v, k.origin});
}

void State::emit_top(int e, std::uint32_t vs, std::uint32_t vt) {
  if (vs == vt) return;
  faces[edges[e].face].half_edges.push_back({vt, vs});
}

std::uint32_t State::vertex_now(int c) {
  const Corner& k = corners[c];
  const glm::dvec3& o = vertices[k.origin];
  // A corner with no direction exists only at the height it was made.
  if (std::abs(o.z - height) <= tol_.height() || k.motion == Motion::Ridge || k.motion == Motion::Ambiguous)
    return k.origin;
  const std::uint32_t v = vertex_at(position(c, height), height);
  emit_trajectory(c, v);
  return v;
}

SpanList State::spans(int e) {
  Edge& edge = edges[e];
  int* link = &edge.first_span;
  edge.last_span = kNone;
  for (int c = edge.first_span; c != kNone; c = corners[c].next_span) {
    if (!corners[c].alive) {
      --edge.listed_spans;
      continue;
    }
    *link = c;
    link = &corners[c].next_span;
    edge.last_span = c;
  }
  *link = kNone;
  return listed_spans(e);
}

int State::span_through(int e, glm::dvec2 p, double z, double reach) const {
  const Edge& edge = edges[e];
  if (std::abs(edge.plane.signed_distance(p, z)) > reach) return kNone;
  // The list as it stands, its stale entries passed over rather than dropped
  // first: spans() reads the whole list, and the span through p is mostly
  // found early in it; a comb's bar, cut at every tooth, has thousands.
  for (int s : listed_spans(e)) {
    const int t = corners[s].next;
    if (!corners[s].alive || t == kNone) continue;
    const double ts = glm::dot(position(s, z) - p, edge.dir);
    const double tt = glm::dot(position(t, z) - p, edge.dir);
    if (ts <= tol_.span_margin() && tt >= -tol_.span_margin()) return s;
  }
  return kNone;
}

}  // namespace procex::engine
