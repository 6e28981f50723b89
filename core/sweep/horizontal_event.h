// Horizontal profile runs (paper 4.4, fig. 17). Where profiles step sideways
// at one height, the whole cross-section is offset there, each edge by its own
// distance. The offset is a nested sweep of the current loops, one slope per
// edge, flattened onto the sweep plane: the faces of edges stepping in face up
// (ledges), those stepping out face down (soffits), and the nested sweep's top
// is the new cross-section. Its loops stay simple where edges meet or vanish
// on the way, because the nested sweep resolves those as events. Where
// neighbours step different ways their flattened faces fold over each other;
// overlaid (core/geom/chain_overlay.h), the folds cancel and the horizontal
// faces are what covers the old cross-section but not the new, or the new
// but not the old.
#pragma once

#include <map>
#include <string>

#include "core/sweep/event_queue.h"
#include "core/sweep/profile_event.h"

namespace procex::engine {

// What a source does at the run's height. Sources not listed keep their plane.
struct SourceStep {
  double inward = 0.0;    // horizontal step, inward positive (0: no step)
  std::string step_tag;   // tag of the horizontal faces it makes
  double slope = 0.0;     // the plane it continues with above the run
  std::string tag;        // that plane's tag
};

// Steps every live loop at the current height. Corners the new cross-section
// has unchanged (made below this height) keep their events and are scheduled
// only against the planes made at this height; the others are replaced and
// scheduled in full.
// A jog made between straight-on neighbours that step differently is a
// source of its own, whose profile events go into `profile_events`.
void apply_horizontal_run(State& st, EventQueue& queue, ProfileEvents& profile_events,
                          const std::map<int, SourceStep>& steps);

}  // namespace procex::engine
