// Random simple polygons (random_simple_polygon: random points untangled by
// 2-opt, not star-shaped, half their corners reflex; class (c) of issue 12).
// Every case must pass every property check_case applies. Two classes:
// 1,000 to 10,000 vertices, every edge at 45 degrees, CGAL's skeleton
// included (its inexact constructions past kExactOracleVertices); and 8 to
// 1,000 vertices under class (b)'s per-edge angles, vertical edges, caps,
// profiles and plan edits, where walls leaning out over the polygons'
// pockets meet roofs that grid plans, whose walls stand apart, do not make;
// and the same polygons of 8 to 1,500 vertices with a quarter of their edges
// vertical on every case (class (b)'s fifth mode), capped.
// Run by hand (ctest -L soak, or PROCEX_SOAK=1); TESTING.md records them.
#include <cstddef>

#include <gtest/gtest.h>

#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

constexpr std::size_t kParts = 4;

class GeneratedLargeRandomPolygons : public ::testing::TestWithParam<std::size_t> {};

TEST_P(GeneratedLargeRandomPolygons, EveryCasePassesEveryProperty) {
  run_generated(CaseClass::LargeRandomPolygons, GetParam(), kParts, {.normal = 12, .soak = 1000, .shrink_tries = 4});
}

INSTANTIATE_TEST_SUITE_P(Parts, GeneratedLargeRandomPolygons, ::testing::Range<std::size_t>(0, kParts));

class GeneratedRandomPolygonsAngles : public ::testing::TestWithParam<std::size_t> {};

TEST_P(GeneratedRandomPolygonsAngles, EveryCasePassesEveryProperty) {
  run_generated(CaseClass::RandomPolygonsAngles, GetParam(), kParts,
                {.normal = 400, .soak = 10000, .shrink_tries = 200});
}

INSTANTIATE_TEST_SUITE_P(Parts, GeneratedRandomPolygonsAngles, ::testing::Range<std::size_t>(0, kParts));

class GeneratedRandomPolygonsWalls : public ::testing::TestWithParam<std::size_t> {};

TEST_P(GeneratedRandomPolygonsWalls, EveryCasePassesEveryProperty) {
  run_generated(CaseClass::RandomPolygonsWalls, GetParam(), kParts,
                {.normal = 400, .soak = 10000, .shrink_tries = 200});
}

INSTANTIATE_TEST_SUITE_P(Parts, GeneratedRandomPolygonsWalls, ::testing::Range<std::size_t>(0, kParts));

}  // namespace
}  // namespace procex::testing
