// One generated input: a footprint with its edges' angles or profiles and the
// sweep's options, from a class and a seed (issue 12 item 2). The same class
// and seed give the same case on every machine (std::mt19937_64 and the
// generators' own distributions of integers; real draws go through
// uniform_real_distribution, which libstdc++ fixes).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/geom/footprint.h"
#include "core/sweep/sweep.h"

namespace procex::testing {

enum class CaseClass {
  Grid,    // (a) grid and letter plans, transformed, one angle
  Angles,  // (b) the same plans under per-edge angles, vertical edges, caps, profiles, plan edits
  Size,    // (c) 1,000 to 10,000 vertices
  // (c) jittered stars: thousands of events within micrometres of one height
  // and the last within about the jitter of one point; of 1,000 to 3,000 and of
  // 3,000 to 12,000 vertices (tests/large/generated_stars_test.cc).
  Stars,
  LargeStars,
  // (c) random simple polygons (random_simple_polygon: 2-opt untangled random
  // points, not star-shaped, half their corners reflex): of 20 to 1,000
  // vertices (tests/core/generated_random_polygons_test.cc) and of 1,000 to
  // 10,000 (tests/large/generated_random_polygons_test.cc).
  RandomPolygons,
  LargeRandomPolygons,
  // (b) on (c): random simple polygons of 8 to 1,000 vertices under class
  // (b)'s angles, profiles, caps and plan edits
  // (tests/core/generated_random_polygons_test.cc).
  RandomPolygonsAngles,
  // (b) on (c): such polygons of 8 to 1,500 vertices, a quarter of their
  // edges vertical, the rest at -60..80 degrees, capped (the same file).
  RandomPolygonsWalls,
};

const char* class_name(CaseClass c);

struct GeneratedCase {
  std::string description;  // class, seed, plan, transform, angles: enough to rebuild it by hand
  Footprint footprint;      // as generated, before prepare_footprint
  SweepOptions options;
  // Names of the profile presets (edge_profiles.h) the footprint's profiles
  // are, in order, and whether options.plan_edits are the preset edits: what
  // a fixture file records to rebuild the case.
  std::vector<std::string> profile_presets;
  bool preset_plan_edits = false;
};

GeneratedCase generate_case(CaseClass c, std::uint64_t seed);

}  // namespace procex::testing
