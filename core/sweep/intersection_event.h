// The generalized intersection event (paper 4.3, fig. 15, 16, 30): any number
// of planes meeting at one point. Edge, split and vertex events are all this.
#pragma once

#include <vector>

#include "core/sweep/event_queue.h"

namespace procex::engine {

// Checks every candidate the sweep plane has just reached against the live
// loops, clusters the real collisions by position (delta3), and rewires the
// loops at each cluster. Throws SweepError if a cluster cannot be resolved.
void resolve_intersections(State& st, EventQueue& queue, const std::vector<Candidate>& batch);

}  // namespace procex::engine
