// Parallel, same-direction edges that become neighbours with different slopes
// (paper 4.5, fig. 18-19, appendix fig. 31): their planes meet only in a
// horizontal line, so the corner between them has no direction. One plane
// takes over the other's span from this height on.
#pragma once

#include <vector>

#include "core/sweep/sweep_state.h"

namespace procex::engine {

// True if corner c sits between parallel same-direction edges whose planes differ.
bool ambiguous(const State& st, int c);

// Resolves the ambiguity at corner c (alive, at the current height): by the
// way its lines cross, where it lies off its neighbours' line by more than
// `straight`, else by the volume rule of the sweep's options. Returns the
// corners that replace it (already linked), which may themselves need
// scheduling.
std::vector<int> resolve_ambiguity(State& st, int c, double straight);

}  // namespace procex::engine
