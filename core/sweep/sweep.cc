// The driver loop (paper 4.1 and appendix C): fill the queue with potential
// events, then repeatedly take every event at the lowest height, resolve it
// against the live loops, and stop when no loop is left (or at the cap).
#include "core/sweep/sweep.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>

#include "core/geom/error.h"
#include "core/sweep/cap_event.h"
#include "core/sweep/driver.h"
#include "core/sweep/plan_edit_event.h"
#include "core/sweep/simple_faces.h"
#include "core/sweep/spares.h"
#include "core/sweep/surface_output.h"

namespace procex {
namespace {

// The footprint's own frame: its bounding box, centred on the origin. The
// engine's arithmetic is on differences of coordinates; far from the origin
// (a city in UTM metres, x = 1e9) the absolute values would eat their digits,
// and a roof would depend on where it stands.
struct LocalFrame {
  glm::dvec2 centre;
  double extent;
  // How far rounding may have moved one point from another: a coordinate
  // carries up to an ulp of its magnitude, the difference of two up to two.
  double rounding;
};

LocalFrame local_frame(const Footprint& fp) {
  glm::dvec2 lo{1e300}, hi{-1e300};
  for (const Loop& l : fp.loops)
    for (glm::dvec2 p : l.points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
  if (!(extent > 0.0) || !std::isfinite(extent)) throw InputError("footprint has no extent");
  const double magnitude = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)});
  return {0.5 * (lo + hi), extent, 2.0 * std::numeric_limits<double>::epsilon() * magnitude};
}

void move(Surface& s, glm::dvec2 by) {
  const glm::dvec3 d{by, 0.0};
  for (glm::dvec3& v : s.vertices) v += d;
  for (auto* resolved : {&s.anchors, &s.plan_edits})
    for (ResolvedAnchor& a : *resolved) {
      a.frame.origin += d;
      a.span_from += d;
      a.span_to += d;
    }
}

// The first plane of a footprint edge, checked: errors name its loop and vertex.
engine::FirstPlane first_plane(engine::State& st, const Footprint& fp, const EdgeSpec& spec, int loop, int vertex) {
  if (spec.profile >= static_cast<int>(fp.profiles.size()))
    throw InputError("edge names profile " + std::to_string(spec.profile) + " but the footprint has " +
                         std::to_string(fp.profiles.size()),
                     loop, vertex);
  if (spec.profile >= 0) {
    const Profile& profile = fp.profiles[static_cast<std::size_t>(spec.profile)];
    check_profile(profile);
    // A step at height 0 would lay a face on the base (inward: a sheet of no
    // thickness); the footprint itself is the place to make an edge wider.
    if (engine::next_plane(profile, 0, st.tol().height()).outward_step != 0.0)
      throw InputError("profile '" + profile.name + "' starts with a horizontal segment; a profile must rise from the "
                       "footprint first (move the footprint edge instead)", loop, vertex);
  }
  try {
    return engine::add_source(st, fp.profiles, spec, 0.0);
  } catch (const InputError& e) {
    throw InputError(e.what(), loop, vertex);
  }
}

// Loads the footprint's loops moved by `by` (into its local frame), a loop at
// a time: a moved copy of the whole footprint, kept through every attempt,
// was 46 MB of the sweep of a square with 512 x 512 holes.
void load(engine::State& st, const Footprint& fp, glm::dvec2 by) {
  st.plan_position.centre = -by;
  engine::FaceGroup base;
  base.kind = FaceKind::Base;
  base.outward = {0.0, 0.0, -1.0};
  st.base_face = static_cast<int>(st.faces.size());
  st.faces.push_back(base);
  // A sweep makes about as many corners again as the plan has (2.00-2.03
  // times the plan's in all, the scale families but the regular polygon's
  // 1.0). Grown by doubling, the array held its old copy and the new one at
  // once, and past 2^21 corners, near the end of the sweep of the square with
  // 512 x 512 holes, that was the sweep's peak (144 MiB over). Room for three
  // times the plan's corners is address space until it is used.
  std::size_t plan_corners = 0;
  for (const Loop& loop : fp.loops) plan_corners += loop.points.size();
  st.corners.reserve(3 * plan_corners);
  for (std::size_t li = 0; li < fp.loops.size(); ++li) {
    const Loop& loop = fp.loops[li];
    const std::size_t n = loop.points.size();
    if (n < 3 || loop.edges.size() != n)
      throw InputError("loop needs at least 3 vertices and one edge spec per vertex", static_cast<int>(li));
    const int s0 = static_cast<int>(st.sources.size());
    std::vector<double> slopes(n);
    std::vector<std::string> tags(n);
    for (std::size_t j = 0; j < n; ++j) {
      engine::FirstPlane first = first_plane(st, fp, loop.edges[j], static_cast<int>(li), static_cast<int>(j));
      slopes[j] = first.slope;
      tags[j] = std::move(first.tag);
    }
    std::vector<glm::dvec2> points = loop.points;
    for (glm::dvec2& p : points) p += by;
    engine::load_loop(st, points, std::move(slopes), tags, s0, static_cast<int>(li));
  }
}

// Whether some edge ends vertical or leaning outward (its last plane never
// meets the others above), so that an open roof is the recipe's, not rounding's.
bool can_rise_forever(const Footprint& fp) {
  for (const Loop& loop : fp.loops)
    for (const EdgeSpec& e : loop.edges) {
      const bool own = e.profile < 0 || static_cast<std::size_t>(e.profile) >= fp.profiles.size();
      const Profile* p = own ? nullptr : &fp.profiles[static_cast<std::size_t>(e.profile)];
      const double last = own || p->segments() == 0 ? e.angle_deg : p->angle_deg(p->segments() - 1);
      if (last <= 0.0) return true;
    }
  return false;
}

// The footprint's roof in the frame centred on `centre` (plan points moved by
// -centre).
Surface sweep_with(const Footprint& footprint, glm::dvec2 centre, const SweepOptions& options,
                   const engine::Tolerances& tol, engine::Budget& budget) {
  budget.start_attempt();
  engine::State st(tol, options, &budget);
  load(st, footprint, -centre);
  // The queue's storage as the thread's last sweep left it (spares.h).
  std::unique_ptr<engine::EventQueue> queue = engine::Spares<engine::EventQueue>::take();
  engine::schedule_all(st, *queue);
  engine::ProfileEvents profile_events;
  for (int s = 0; s < static_cast<int>(st.sources.size()); ++s) profile_events.schedule(st, s);
  engine::AnchorEvents anchors(st, options.anchors);
  engine::PlanEditEvents plan_edits(st, footprint.profiles);
  engine::run_events(st, *queue, profile_events, &anchors, &plan_edits);
  queue->clear();
  engine::Spares<engine::EventQueue>::give(std::move(queue), st.corners.size());
  const bool open = std::any_of(st.corners.begin(), st.corners.end(), [](const engine::Corner& c) { return c.alive; });
  if (open) {
    if (!options.max_height && can_rise_forever(footprint))
      throw SweepOpenError(
          "sweep: the roof does not close (vertical or outward-leaning edges rise forever); give a maximum height",
          st.height, {});
    if (!options.max_height) {
      char width[32];
      std::snprintf(width, sizeof width, "%.3g", tol.position());
      throw SweepError(std::string("sweep: the roof does not close although every edge leans inward, so rounding lost "
                                   "the events that close it: the plan is likely too thin somewhere for the sweep "
                                   "(sides closer than about ") +
                           width + " m); widen it, or give a maximum height",
                       st.height, {});
    }
    engine::cap_at(st, std::max(st.height, *options.max_height));
  }
  Surface surface = engine::build_surface(st);
  // A plan whose every event fell within the clustering height of its base
  // (a triangle 8e-7 m thin and 9 m long) comes out flat: no solid, and the
  // validator's "faces point inwards" would blame the wrong thing.
  if (std::none_of(surface.vertices.begin(), surface.vertices.end(), [](const glm::dvec3& v) { return v.z > 0.0; }))
    throw SweepError("sweep: the roof has no height: every event fell within the clustering distance of the base, so "
                     "the plan is too thin for the sweep everywhere; widen it",
                     0.0, {});
  engine::close_surface(surface, st.plan_position);
  if (st.shared_instant) engine::check_simple_faces(surface);
  surface.anchors = anchors.finish();
  surface.plan_edits = plan_edits.finish();
  return surface;
}

std::atomic<std::uint64_t> retried{0};

}  // namespace

std::uint64_t sweeps_retried() { return retried.load(std::memory_order_relaxed); }

Surface sweep(const Footprint& footprint, const SweepOptions& options) {
  const LocalFrame frame = local_frame(footprint);
  engine::Tolerances tol{frame.extent};
  tol.rounding = frame.rounding;
  std::size_t plan_vertices = 0;
  for (const Loop& loop : footprint.loops) plan_vertices += loop.points.size();
  engine::Budget budget(options.budget, plan_vertices);
  // What to report if no scale closes: the first refusal by the budget (the
  // one error with a knob: raising that limit may close the scale it
  // stopped), else the first attempt's error, of its own type (an open roof
  // stays one).
  std::exception_ptr first, refused;
  int retries = 0;
  // A clustering distance finer than the rounding the plan took where it
  // stands (a footprint a few centimetres across at x = 5e6) would tell
  // points apart by where it stands: such scales are not tried, the coarsest
  // always is.
  for (double relative : engine::Tolerances::retry_relative) {
    if (relative * frame.extent < frame.rounding && relative != engine::Tolerances::coarsest_relative) continue;
    tol.relative = relative;
    try {
      Surface s = sweep_with(footprint, frame.centre, options, tol, budget);
      move(s, frame.centre);
      s.tolerance_relative = relative;
      s.retries = retries;
      if (retries > 0) retried.fetch_add(1, std::memory_order_relaxed);
      return s;
    } catch (const SweepBudgetError&) {
      // Not a runaway at every scale: events rounding kept apart at a fine one
      // (thousands of corners a few micrometres from one apex, each meeting
      // every plane there) may be one at the next. The deadline spans every
      // attempt, so the retries stay within the time budget.
      if (!refused) refused = std::current_exception();
      ++retries;
    } catch (const SweepError&) {
      if (!first) first = std::current_exception();
      ++retries;
    }
  }
  std::rethrow_exception(refused ? refused : first);
}

}  // namespace procex
