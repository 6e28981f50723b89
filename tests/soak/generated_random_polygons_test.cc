// Random simple polygons (random_simple_polygon: random points untangled by
// 2-opt, not star-shaped, half their corners reflex; class (c) of issue 12)
// of 1,000 to 10,000 vertices, every edge at 45 degrees: every case must pass
// every property check_case applies, CGAL's skeleton included (its inexact
// constructions past kExactOracleVertices). The smaller ones, and those under
// class (b)'s angles, are in tests/core/generated_random_polygons_test.cc.
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

}  // namespace
}  // namespace procex::testing
