// A corner between two edges running back along each other (a ridge corner,
// anti-parallel planes) is the tip of a spike of no width: the two sides
// overlap from the tip back to the nearer of their far ends. The spike closes
// at once along that overlap, leaving a horizontal ridge between the two faces.
#pragma once

#include <vector>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Closes the spike at ridge corner c (alive, at the current height). Returns
// the corners that replace the tip (already linked), for scheduling.
std::vector<int> close_spike(State& st, int c);

}  // namespace procex::engine
