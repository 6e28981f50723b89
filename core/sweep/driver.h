// The parts of a sweep that nested sweeps (horizontal profile runs) reuse:
// loading loops into a state and running its events up to a height.
#pragma once

#include <string>
#include <vector>

#include "core/sweep/anchor_event.h"
#include "core/sweep/event_queue.h"
#include "core/sweep/profile_event.h"
#include "core/sweep/sweep_state.h"

namespace procex::engine {

class PlanEditEvents;

// The slope of a constant angle in degrees from the vertical (clamped short
// of horizontal). Throws InputError outside [-90, 90].
double slope_of(double angle_deg);

// The first plane of an edge whose profile starts at height `base`.
struct FirstPlane {
  double slope;
  std::string tag;
};
// Adds the source of edge `spec` (its profile, if any, indexes `profiles`, is
// valid and rises first) and returns its first plane.
FirstPlane add_source(State& st, const std::vector<Profile>& profiles, const EdgeSpec& spec, double base);

// Whether the corner at the start of edge j (of the loop through `points`,
// edges along unit `dirs`) runs straight on: its neighbours point the same way
// and it lies within `position` of their line.
bool runs_straight(const std::vector<glm::dvec2>& points, const std::vector<glm::dvec2>& dirs, std::size_t j,
                   double position);

// The unit direction of each edge of the loop through `points`. Throws
// InputError for fewer than 3 points or a zero-length edge (`loop` names it).
std::vector<glm::dvec2> edge_directions(const std::vector<glm::dvec2>& points, int loop);

// Adds one closed loop: edge j runs from points[j] to points[j + 1] with
// slope slopes[j] and face tag tags[j], and belongs to source first_source + j
// (already in st.sources). Collinear neighbours with different slopes take the
// one the ambiguity rule picks. `loop` names the loop in errors.
void load_loop(State& st, const std::vector<glm::dvec2>& points, std::vector<double> slopes,
               const std::vector<std::string>& tags, int first_source, int loop);

// Adds one closed loop as given: edge j runs from points[j] along dirs[j]
// (which a zero-length edge needs) with slope slopes[j]; nothing is unified.
void load_edges(State& st, const std::vector<glm::dvec2>& points, const std::vector<glm::dvec2>& dirs,
                const std::vector<double>& slopes, const std::vector<std::string>& tags, int first_source);

// Queues every live corner's potential events.
void schedule_all(State& st, EventQueue& queue);

// Resolves events in height order until none is left at or below the
// options' max height. Corners still alive afterwards are open loops. Anchors
// resolve on the loops as they are at their height, before events there;
// plan edits are inserted after the collisions below them and before the
// profile events at their height.
void run_events(State& st, EventQueue& queue, ProfileEvents& profile_events, AnchorEvents* anchors = nullptr,
                PlanEditEvents* plan_edits = nullptr);

}  // namespace procex::engine
