// New corners that have no direction of their own are settled before
// anything is scheduled: loops of no area close into ridges, spikes fold,
// ambiguous neighbours resolve (paper 4.5).
#pragma once

#include <vector>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Settles the corners just made (and those their settling makes); `live`
// becomes the ones still alive, in order, ready for scheduling. A corner off
// its neighbours' line by no more than `straight` is taken as straight
// (resolve_ambiguity): the plan's own corners are known to its rounding
// (SweepTolerances::straight), those the sweep makes to the clustering
// distance (position; the lines of plan edits and profiles are worked out).
void settle(State& st, const std::vector<int>& made, std::vector<int>& live, double straight);

}  // namespace procex::engine
