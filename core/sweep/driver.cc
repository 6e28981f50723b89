#include "core/sweep/driver.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/sweep/ambiguity.h"
#include "core/sweep/intersection_event.h"
#include "core/sweep/plan_edit_event.h"

namespace procex::engine {
namespace {

// Collinear neighbouring edges with different slopes are the ambiguous case
// (paper 4.5) from the start: the whole run takes the slope the volume rule
// picks, so each edge keeps its own (coplanar) face. Collinear as drawn, up
// to rounding (straight()): a corner bent by more, though within the
// clustering distance, runs along its lines one way, and a run that took
// the volume rule's slope put a 5.4 m edge's face 0.4 m off its plane where
// the corner ran into its 4.6 cm neighbour
// (generated_random_polygons_scan_2732).
void unify_collinear_slopes(const std::vector<glm::dvec2>& points, const std::vector<glm::dvec2>& dirs,
                            std::vector<double>& slopes, Ambiguity rule, double straight) {
  const std::size_t n = dirs.size();
  std::size_t start = 0;
  while (start < n && runs_straight(points, dirs, start, straight)) ++start;
  if (start == n) return;  // no corner at all: not a polygon, refused elsewhere
  for (std::size_t i = 0; i < n;) {
    const std::size_t first = (start + i) % n;
    std::size_t len = 1;
    while (i + len < n && runs_straight(points, dirs, (first + len) % n, straight)) ++len;
    double pick = slopes[first];
    for (std::size_t m = 0; m < len; ++m) {
      const double k = slopes[(first + m) % n];
      pick = rule == Ambiguity::MaximizeVolume ? std::min(pick, k) : std::max(pick, k);
    }
    for (std::size_t m = 0; m < len; ++m) slopes[(first + m) % n] = pick;
    i += len;
  }
}

}  // namespace

// A corner is straight when it lies within the clustering distance of its
// neighbours' line (the sine of its turn times the shorter edge): a plan drawn
// straight keeps that rule wherever it is, though far from the origin its
// coordinates' rounding turns it by far more than a fixed sine.
bool runs_straight(const std::vector<glm::dvec2>& points, const std::vector<glm::dvec2>& dirs, std::size_t j,
                   double position) {
  const std::size_t n = dirs.size();
  const glm::dvec2 a = dirs[(j + n - 1) % n], b = dirs[j];
  const double shorter = std::min(glm::distance(points[(j + n - 1) % n], points[j]),
                                  glm::distance(points[j], points[(j + 1) % n]));
  return glm::dot(a, b) > 0.0 &&
         (std::abs(cross(a, b)) <= Tolerances::parallel_sin || std::abs(cross(a, b)) * shorter <= position);
}

std::vector<glm::dvec2> edge_directions(const std::vector<glm::dvec2>& points, int loop) {
  const std::size_t n = points.size();
  if (n < 3) throw InputError("loop needs at least 3 vertices and one edge spec per vertex", loop);
  std::vector<glm::dvec2> dirs(n);
  for (std::size_t j = 0; j < n; ++j) {
    const glm::dvec2 d = points[(j + 1) % n] - points[j];
    const double len = glm::length(d);
    if (!(len > 0.0)) throw InputError("zero-length edge", loop, static_cast<int>(j));
    dirs[j] = d / len;
  }
  return dirs;
}

double slope_of(double angle_deg) {
  if (!(angle_deg >= -90.0 && angle_deg <= 90.0)) throw InputError("edge angle outside [-90, 90] degrees");
  const double k = std::tan(angle_deg * M_PI / 180.0);
  return std::clamp(k, -Tolerances::max_slope, Tolerances::max_slope);
}

FirstPlane add_source(State& st, const std::vector<Profile>& profiles, const EdgeSpec& spec, double base) {
  Source src;
  src.id = spec.id;
  src.base = base;
  if (spec.profile < 0) {
    st.sources.push_back(src);
    return {slope_of(spec.angle_deg), {}};
  }
  const Profile& profile = profiles[static_cast<std::size_t>(spec.profile)];
  const NextPlane next = next_plane(profile, 0, st.tol().height());
  src.profile = &profile;
  src.profile_index = spec.profile;
  src.point = next.point;
  st.sources.push_back(src);
  return {segment_slope(profile, next.segment), profile.tags.empty() ? std::string() : profile.tags[next.segment]};
}

void load_loop(State& st, const std::vector<glm::dvec2>& points, std::vector<double> slopes,
               const std::vector<std::string>& tags, int first_source, int loop) {
  const std::vector<glm::dvec2> dirs = edge_directions(points, loop);
  unify_collinear_slopes(points, dirs, slopes, st.options().ambiguity, st.tol().straight());
  const std::size_t first = st.corners.size();
  load_edges(st, points, dirs, slopes, tags, first_source);
  // A corner between lines so nearly parallel that it would run faster than
  // any corner may (bent, so not straight) is resolved where it starts, as
  // one made later is when settled. A loop no wider than the clustering
  // distance is left to the sweep, which says so (a needle).
  const std::size_t made = st.corners.size();
  for (std::size_t c = first; c < made; ++c)
    if (st.corners[c].alive && ambiguous(st, static_cast<int>(c)))
      resolve_ambiguity(st, static_cast<int>(c), st.tol().straight());
}

void load_edges(State& st, const std::vector<glm::dvec2>& points, const std::vector<glm::dvec2>& dirs,
                const std::vector<double>& slopes, const std::vector<std::string>& tags, int first_source) {
  const std::size_t n = points.size();
  const auto v0 = static_cast<std::uint32_t>(st.vertices.size());
  for (glm::dvec2 p : points) st.add_vertex({p, st.height});
  const int e0 = static_cast<int>(st.edges.size());
  for (std::size_t j = 0; j < n; ++j) {
    Source& src = st.sources[static_cast<std::size_t>(first_source) + j];
    src.start = points[j];
    src.end = points[(j + 1) % n];
    st.add_edge(points[j], st.height, dirs[j], slopes[j], first_source + static_cast<int>(j), tags[j]);
    const auto va = v0 + static_cast<std::uint32_t>(j), vb = v0 + static_cast<std::uint32_t>((j + 1) % n);
    st.faces[st.edges.back().face].half_edges.push_back({va, vb});
    st.faces[st.base_face].half_edges.push_back({vb, va});
  }
  const int c0 = static_cast<int>(st.corners.size());
  for (std::size_t j = 0; j < n; ++j) {
    const int prev = e0 + static_cast<int>((j + n - 1) % n), next = e0 + static_cast<int>(j);
    st.add_corner(prev, next, v0 + static_cast<std::uint32_t>(j));
  }
  for (std::size_t j = 0; j < n; ++j) st.link(c0 + static_cast<int>(j), c0 + static_cast<int>((j + 1) % n));
}

void schedule_all(State& st, EventQueue& queue) {
  queue.start(st);
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c)
    if (st.corners[c].alive) queue.schedule(st, c);
}

void run_events(State& st, EventQueue& queue, ProfileEvents& profile_events, AnchorEvents* anchors,
                PlanEditEvents* plan_edits) {
  const std::optional<double> max_height = st.options().max_height;
  auto anchors_up_to = [&](double z) {
    if (anchors) anchors->resolve_up_to(st, max_height ? std::min(z, *max_height) : z);
  };
  std::size_t stalled = 0, stall_limit = 0;
  double last = -1.0;
  auto edits_pending = [&] { return plan_edits && !plan_edits->empty(); };
  for (;;) {
    queue.catch_up(st);
    if (queue.empty() && profile_events.empty() && !edits_pending()) break;
    // Collisions at a profile vertex's or a plan edit's height are resolved before the planes change.
    const double z_collide = queue.empty() ? HUGE_VAL : queue.next_height();
    const double z_profile = profile_events.empty() ? HUGE_VAL : profile_events.next_height();
    const double z_edit = edits_pending() ? plan_edits->next_height() : HUGE_VAL;
    anchors_up_to(std::min({z_collide, z_profile, z_edit}));
    if (z_edit < z_collide - st.tol().height() && z_edit <= z_profile + st.tol().height()) {
      if ((max_height && z_edit > *max_height) || z_edit == HUGE_VAL) break;
      st.height = std::max(st.height, z_edit);
      plan_edits->apply_next(st, queue, profile_events);
      continue;
    }
    if (z_profile < z_collide - st.tol().height()) {
      if (max_height && z_profile > *max_height) break;
      st.height = std::max(st.height, z_profile);
      apply_profile_events(st, queue, profile_events, profile_events.pop(st.tol().height()));
      continue;
    }
    const double z = z_collide;
    if (max_height && z > *max_height) break;
    if (z > st.tol().runaway_height()) break;
    // Bounded work: every event removes a span or splits one, so a sweep that
    // keeps resolving events at one height without rising is going in circles.
    if (z > last + st.tol().height()) {
      stalled = 0;
      stall_limit = 8 * st.corners.size() + 64;
    } else {
      ++stalled;
    }
    last = std::max(last, z);
    if (stalled > stall_limit) {
      throw SweepError("sweep: events repeat without rising at height " + std::to_string(st.height), st.height, {});
    }
    st.height = std::max(st.height, z);
    st.check_time();
    resolve_intersections(st, queue, queue.pop_cluster(st));
  }
  // Open loops (capped) still carry anchors up to the cap.
  anchors_up_to(max_height.value_or(st.height));
}

}  // namespace procex::engine
