// Minimising a failing generated case (issue 12 item 3): drop loops and
// vertices (halving a long loop first), then round coordinates, angles and max_height, keeping each step
// while the case still fails; and writing it as a GeoJSON fixture that
// tests/core/generated_fixtures_test.cc and `procex roof` read back.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "core/io/geojson.h"
#include "tests/support/generators/generated_case.h"

namespace procex::testing {

// The smallest case reached from `c` by steps that keep `fails` true, trying
// at most max_tries candidates.
GeneratedCase shrink(GeneratedCase c, const std::function<bool(const GeneratedCase&)>& fails, std::size_t max_tries);

// One feature: the loops (17 significant digits, closed), properties
// "angles" (per loop, per edge), "max_height", "profiles" (preset names per
// edge, space separated, "-" for none), "plan_edits" ("presets"),
// "generator" (the description) and "problem".
std::string fixture_geojson(const GeneratedCase& c, const std::string& problem);

// The case a fixture_geojson() feature describes. Throws std::invalid_argument
// naming the property that is wrong.
GeneratedCase case_from_fixture(const GeoJsonFeature& feature);

}  // namespace procex::testing
