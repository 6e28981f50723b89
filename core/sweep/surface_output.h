// Turns the half-edges each face collected during the sweep into the planar
// face loops of a Surface.
#pragma once

#include "core/mesh/surface.h"
#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Throws SweepError naming the face's source edge if a face's boundary does not close.
Surface build_surface(const State& st);

// Throws SweepError unless every boundary edge of the surface meets its
// reverse exactly once (closed and consistently oriented).
void check_closed(const Surface& surface);

}  // namespace procex::engine
