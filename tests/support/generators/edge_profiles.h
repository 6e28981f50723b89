// The profiles and plan edits class (b) puts on generated plans: the house
// presets of tests/support/house_profiles.h (soffit, ledge, mansard, fascia,
// lean) plus a plain house and a gambrel, by name, and a bay, a dormer and a
// recess under a hip roof as the plan edit corpus test places them.
#pragma once

#include <string>
#include <vector>

#include "core/geom/plan_edit.h"
#include "core/geom/profile.h"

namespace procex::testing {

// Every preset's name, in a fixed order.
std::vector<std::string> profile_preset_names();
// Throws std::invalid_argument for a name profile_preset_names() does not list.
Profile profile_preset(const std::string& name);

// The profiles the preset plan edits use, by name: hip (for the footprint's
// edges), bay, dormer, recess.
std::vector<std::string> plan_edit_profile_names();
// A natural bay at 1 m and a dormer at 3 m in the middle of every edge and a
// forced recess 1 m from every edge's start, their edges' profiles indexing
// plan_edit_profile_names().
std::vector<PlanEdit> preset_plan_edits();

}  // namespace procex::testing
