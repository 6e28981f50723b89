// Turns the half-edges each face collected during the sweep into the planar
// face loops of a Surface.
#pragma once

#include "core/mesh/surface.h"
#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Throws SweepError naming the face's source edge if a face's boundary does not close.
Surface build_surface(const State& st);

// Throws SweepError unless every boundary edge of the surface meets its
// reverse exactly once (closed and consistently oriented), naming vertices by
// `plan_position`. Where parts of the solid touch at a vertex, each fan of
// faces round it gets its own copy of the vertex, so the surface is a
// 2-manifold.
void close_surface(Surface& surface, const PlanPosition& plan_position);

}  // namespace procex::engine
