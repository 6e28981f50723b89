// Class (c) of issue 12 item 2, random simple polygons of 20 to 1,000
// vertices (random_simple_polygon: random points untangled by 2-opt): plans
// with pockets inside pockets that no point sees whole, where the other
// classes' many-vertex plans are star-shaped; and (b) on (c): such polygons
// of 8 to 1,000 vertices under class (b)'s per-edge angles, vertical edges,
// caps, profiles and plan edits, and of 8 to 1,500 vertices with a quarter of
// their edges vertical on every case, capped, where walls leaning out over
// the polygons' pockets meet roofs that grid plans, whose walls stand apart,
// do not make. Every case must pass every property check_case applies,
// CGAL's skeleton included; those of 1,000 to 10,000 vertices are in
// tests/large.
#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

PROCEX_GENERATED_CLASS(GeneratedRandomPolygons, CaseClass::RandomPolygons, 4,
                       {.normal = 100, .soak = 2000, .shrink_tries = 100});

PROCEX_GENERATED_CLASS(GeneratedRandomPolygonsAngles, CaseClass::RandomPolygonsAngles, 4,
                       {.normal = 400, .soak = 10000, .shrink_tries = 200});

PROCEX_GENERATED_CLASS(GeneratedRandomPolygonsWalls, CaseClass::RandomPolygonsWalls, 4,
                       {.normal = 400, .soak = 10000, .shrink_tries = 200});

}  // namespace
}  // namespace procex::testing
