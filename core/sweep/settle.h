// New corners that have no direction of their own are settled before
// anything is scheduled: loops of no area close into ridges, spikes fold,
// ambiguous neighbours resolve (paper 4.5).
#pragma once

#include <vector>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Settles the corners just made (and those their settling makes); `live`
// becomes the ones still alive, in order, ready for scheduling. An ambiguous
// corner off its neighbours' line by no more than the clustering distance is
// taken as straight (resolve_ambiguity): the sweep knows the corners it
// makes, and the lines of plan edits and profiles it works out, no better.
void settle(State& st, const std::vector<int>& made, std::vector<int>& live);

}  // namespace procex::engine
