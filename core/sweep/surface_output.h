// Turns the half-edges each face collected during the sweep into the planar
// face loops of a Surface.
#pragma once

#include "core/mesh/surface.h"
#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Throws SweepError naming the face's source edge if a face's boundary does not close.
Surface build_surface(const State& st);

}  // namespace procex::engine
