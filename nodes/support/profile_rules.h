// The rule text of the Assign Profiles node: which profile each edge gets,
// by edge labels, with probabilities (paper 3.7).
//
//   street = gable; back long = hip:0.7, mansard:0.3; #4 = 2; * = hip
//
// Rules are separated by ';' or newlines and tried in order; the first whose
// labels all match an edge decides. Labels: short, medium, long; street, side,
// back; outer, inner; selected (the node's selection); party (shared with a
// neighbouring footprint); #<edge id>;
// normal:<from>-<to> (degrees, counter-clockwise from +x, may wrap past 360);
// * (any edge). Choices name a profile by its name or its index in the list,
// each with an optional weight (default 1).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/geom/profile.h"
#include "nodes/support/edge_labels.h"

namespace procex {

struct ProfileChoice {
  std::size_t profile = 0;  // index into the profile list
  double weight = 1.0;
};

struct ProfileRule {
  std::vector<std::string> labels;  // all must match
  std::vector<ProfileChoice> choices;
};

// Throws std::invalid_argument naming the rule (1-based) and the offending
// text: unknown labels, unknown profile names, bad weights.
std::vector<ProfileRule> parse_profile_rules(std::string_view text, const std::vector<Profile>& profiles);

// Whether rule label `label` holds for edge `e` (selected: e's id is in the node's selection).
bool label_matches(std::string_view label, const EdgeLabels& e, bool selected);

// Picks among choices with u in [0, 1).
std::size_t pick_profile(const std::vector<ProfileChoice>& choices, double u);

}  // namespace procex
