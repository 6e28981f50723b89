// The sweep stops at a maximum height: every loop still on the sweep plane
// becomes a horizontal cap face.
#pragma once

#include "core/sweep/sweep_state.h"

namespace procex::engine {

// Closes every live loop at height h with a cap face (kind Cap, facing up).
void cap_at(State& st, double h);

}  // namespace procex::engine
