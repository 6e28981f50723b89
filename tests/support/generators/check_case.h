// Runs every property that applies to a generated case (tests/support/
// roof_properties.h, skeleton_oracle.h): the mesh validates and its faces lie
// on their edges' planes; an inward roof tiles its footprint and has the
// right heights (and, for a rectangle or regular polygon, the volume of its
// integrated offset areas); one angle everywhere agrees with CGAL; and a
// quarter turn, a mirror and a move to (5e5, 5e6) give the same roof moved.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tests/support/generators/generated_case.h"

namespace procex::testing {

struct CaseResult {
  bool refused = false;  // prepare_footprint refused the input (a generator's bug, or a shrink gone too far)
  std::vector<std::string> problems;
  bool failed() const { return refused || !problems.empty(); }
};

struct CheckSelection {
  bool oracle = true;      // compare with CGAL where every edge has one inward angle
  bool transforms = true;  // sweep the transformed inputs too
};

CaseResult check_case(const GeneratedCase& c, const CheckSelection& selection = {});

// The plans check_case sweeps besides the case's own (prepared) plan, each
// named: its transforms, and with CGAL as the oracle the plan it compares
// (straight vertices dropped). What tests/tools/roof_hashes.cc fingerprints to show
// that an engine change leaves every sweep of a soak the same.
std::vector<std::pair<std::string, Footprint>> checked_plans(const Footprint& prepared, const SweepOptions& options,
                                                             const CheckSelection& selection = {});

}  // namespace procex::testing
