// Random simple polygons (random_simple_polygon: random points untangled by
// 2-opt, not star-shaped, half their corners reflex; class (c) of issue 12)
// of 1,000 to 10,000 vertices, every edge at 45 degrees: every case must pass
// every property check_case applies, CGAL's skeleton included (its inexact
// constructions past kExactOracleVertices). The smaller ones, and those under
// class (b)'s angles, are in tests/core/generated_random_polygons_test.cc.
// CI runs the normal budget in the Release build (label slow), the soak one
// runs by hand (PROCEX_SOAK=1); TESTING.md records them.
#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

PROCEX_GENERATED_CLASS(GeneratedLargeRandomPolygons, CaseClass::LargeRandomPolygons, 4,
                       {.normal = 12, .soak = 1000, .shrink_tries = 4});

}  // namespace
}  // namespace procex::testing
