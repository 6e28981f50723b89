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

// Adds one closed loop: edge j runs from points[j] to points[j + 1] with
// slope slopes[j] and face tag tags[j], and belongs to source first_source + j
// (already in st.sources). Collinear neighbours with different slopes take the
// one the ambiguity rule picks. `loop` names the loop in errors.
void load_loop(State& st, const std::vector<glm::dvec2>& points, std::vector<double> slopes,
               const std::vector<std::string>& tags, int first_source, int loop);

// Queues every live corner's potential events.
void schedule_all(State& st, EventQueue& queue);

// Resolves events in height order until none is left at or below the
// options' max height. Corners still alive afterwards are open loops. Anchors
// resolve on the loops as they are at their height, before events there.
void run_events(State& st, EventQueue& queue, ProfileEvents& profile_events, AnchorEvents* anchors = nullptr);

}  // namespace procex::engine
