// The driver loop (paper 4.1 and appendix C): fill the queue with potential
// events, then repeatedly take every event at the lowest height, resolve it
// against the live loops, and stop when no loop is left (or at the cap).
#include "core/sweep/sweep.h"

#include <algorithm>
#include <optional>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/sweep/cap_event.h"
#include "core/sweep/event_queue.h"
#include "core/sweep/intersection_event.h"
#include "core/sweep/profile_event.h"
#include "core/sweep/surface_output.h"

namespace procex {
namespace {

engine::Tolerances tolerances_for(const Footprint& fp) {
  glm::dvec2 lo{1e300}, hi{-1e300};
  for (const Loop& l : fp.loops)
    for (glm::dvec2 p : l.points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(extent > 0.0) || !std::isfinite(extent)) throw InputError("footprint has no extent");
  return {extent};
}

double slope_of(double angle_deg) {
  if (!(angle_deg >= -90.0 && angle_deg <= 90.0)) throw InputError("edge angle outside [-90, 90] degrees");
  const double k = std::tan(angle_deg * M_PI / 180.0);
  return std::clamp(k, -engine::Tolerances::max_slope, engine::Tolerances::max_slope);
}

// Collinear neighbouring edges with different slopes are the ambiguous case
// (paper 4.5) from the start: the whole run takes the slope the volume rule
// picks, so each edge keeps its own (coplanar) face.
void unify_collinear_slopes(const std::vector<glm::dvec2>& dirs, std::vector<double>& slopes, Ambiguity rule) {
  const std::size_t n = dirs.size();
  auto straight = [&](std::size_t j) {  // the corner at the start of edge j
    const glm::dvec2 a = dirs[(j + n - 1) % n], b = dirs[j];
    return std::abs(engine::cross(a, b)) <= engine::Tolerances::parallel_sin && glm::dot(a, b) > 0.0;
  };
  std::size_t start = 0;
  while (start < n && straight(start)) ++start;
  if (start == n) return;  // no corner at all: not a polygon, refused elsewhere
  for (std::size_t i = 0; i < n;) {
    const std::size_t first = (start + i) % n;
    std::size_t len = 1;
    while (i + len < n && straight((first + len) % n)) ++len;
    double pick = slopes[first];
    for (std::size_t m = 0; m < len; ++m) {
      const double k = slopes[(first + m) % n];
      pick = rule == Ambiguity::MaximizeVolume ? std::min(pick, k) : std::max(pick, k);
    }
    for (std::size_t m = 0; m < len; ++m) slopes[(first + m) % n] = pick;
    i += len;
  }
}

// The first plane of an edge: its profile's first slope (after any flat run
// at the base, not handled yet), or its constant angle.
struct FirstPlane {
  double slope;
  std::string tag;
};
FirstPlane first_plane(engine::State& st, const Footprint& fp, const EdgeSpec& spec, int loop, int vertex) {
  engine::Source src;
  src.id = spec.id;
  if (spec.profile < 0) {
    st.sources.push_back(src);
    return {slope_of(spec.angle_deg), {}};
  }
  if (spec.profile >= static_cast<int>(fp.profiles.size()))
    throw InputError("edge names profile " + std::to_string(spec.profile) + " but the footprint has " +
                         std::to_string(fp.profiles.size()),
                     loop, vertex);
  const Profile& profile = fp.profiles[static_cast<std::size_t>(spec.profile)];
  check_profile(profile);
  const engine::NextPlane next = engine::next_plane(profile, 0);
  if (next.outward_step != 0.0)
    throw InputError("profile '" + profile.name + "': a horizontal segment at the base is not supported yet", loop,
                     vertex);
  src.profile = &profile;
  src.point = next.point;
  st.sources.push_back(src);
  return {engine::segment_slope(profile, next.segment), profile.tags.empty() ? std::string() : profile.tags[next.segment]};
}

void load(engine::State& st, const Footprint& fp) {
  engine::FaceGroup base;
  base.kind = FaceKind::Base;
  base.outward = {0.0, 0.0, -1.0};
  st.base_face = static_cast<int>(st.faces.size());
  st.faces.push_back(base);
  for (std::size_t li = 0; li < fp.loops.size(); ++li) {
    const Loop& loop = fp.loops[li];
    const std::size_t n = loop.points.size();
    if (n < 3 || loop.edges.size() != n)
      throw InputError("loop needs at least 3 vertices and one edge spec per vertex", static_cast<int>(li));
    const auto v0 = static_cast<std::uint32_t>(st.vertices.size());
    for (glm::dvec2 p : loop.points) st.add_vertex({p, 0.0});
    const int e0 = static_cast<int>(st.edges.size());
    const int s0 = static_cast<int>(st.sources.size());
    std::vector<glm::dvec2> dirs(n);
    std::vector<double> slopes(n);
    std::vector<std::string> tags(n);
    for (std::size_t j = 0; j < n; ++j) {
      const glm::dvec2 d = loop.points[(j + 1) % n] - loop.points[j];
      const double len = glm::length(d);
      if (!(len > 0.0)) throw InputError("zero-length edge", static_cast<int>(li), static_cast<int>(j));
      dirs[j] = d / len;
      FirstPlane first = first_plane(st, fp, loop.edges[j], static_cast<int>(li), static_cast<int>(j));
      slopes[j] = first.slope;
      tags[j] = std::move(first.tag);
    }
    unify_collinear_slopes(dirs, slopes, st.options().ambiguity);
    for (std::size_t j = 0; j < n; ++j) {
      st.add_edge(loop.points[j], 0.0, dirs[j], slopes[j], s0 + static_cast<int>(j), tags[j]);
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
}

Surface sweep_with(const Footprint& footprint, const SweepOptions& options, const engine::Tolerances& tol) {
  engine::State st(tol, options);
  load(st, footprint);
  engine::EventQueue queue;
  for (int c = 0; c < static_cast<int>(st.corners.size()); ++c)
    if (st.corners[c].alive) queue.schedule(st, c);
  engine::ProfileEvents profile_events;
  for (int s = 0; s < static_cast<int>(st.sources.size()); ++s) profile_events.schedule(st, s);

  // Bounded work: every event removes a span or splits one, so a sweep that
  // keeps resolving events at one height without rising is going in circles.
  const std::size_t n = st.corners.size();
  const std::size_t stall_limit = 8 * n + 64;
  std::size_t stalled = 0;
  double last = -1.0;
  while (!queue.empty() || !profile_events.empty()) {
    // Collisions at a profile vertex's height are resolved before the planes change.
    const double z_collide = queue.empty() ? HUGE_VAL : queue.next_height();
    const double z_profile = profile_events.empty() ? HUGE_VAL : profile_events.next_height();
    if (z_profile < z_collide - st.tol().height()) {
      if (options.max_height && z_profile > *options.max_height) break;
      st.height = std::max(st.height, z_profile);
      engine::apply_profile_events(st, queue, profile_events, profile_events.pop(st.tol().height()));
      continue;
    }
    const double z = z_collide;
    if (options.max_height && z > *options.max_height) break;
    if (z > st.tol().runaway_height()) break;
    stalled = z > last + st.tol().height() ? 0 : stalled + 1;
    last = std::max(last, z);
    if (stalled > stall_limit) {
      throw SweepError("sweep: events repeat without rising at height " + std::to_string(st.height), st.height, {});
    }
    st.height = std::max(st.height, z);
    resolve_intersections(st, queue, queue.pop_cluster(st.tol().height()));
  }
  const bool open = std::any_of(st.corners.begin(), st.corners.end(), [](const engine::Corner& c) { return c.alive; });
  if (open) {
    if (!options.max_height) {
      throw SweepError(
          "sweep: the roof does not close (vertical or outward-leaning edges rise forever); give a maximum height",
          st.height, {});
    }
    engine::cap_at(st, std::max(st.height, *options.max_height));
  }
  Surface surface = engine::build_surface(st);
  engine::check_closed(surface);
  return surface;
}

}  // namespace

Surface sweep(const Footprint& footprint, const SweepOptions& options) {
  engine::Tolerances tol = tolerances_for(footprint);
  std::optional<SweepError> first;
  for (double relative : engine::Tolerances::retry_relative) {
    tol.relative = relative;
    try {
      return sweep_with(footprint, options, tol);
    } catch (const SweepError& e) {
      if (!first) first = e;
    }
  }
  throw *first;
}

}  // namespace procex
