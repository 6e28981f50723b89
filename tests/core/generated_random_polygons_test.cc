// Class (c) of issue 12 item 2, random simple polygons of 20 to 1,000
// vertices (random_simple_polygon: random points untangled by 2-opt): plans
// with pockets inside pockets that no point sees whole, where the other
// classes' many-vertex plans are star-shaped. Every case must pass every
// property check_case applies, CGAL's skeleton included; those of 1,000 to
// 10,000 vertices are in tests/soak.
#include <cstddef>

#include <gtest/gtest.h>

#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

constexpr std::size_t kParts = 4;

class GeneratedRandomPolygons : public ::testing::TestWithParam<std::size_t> {};

TEST_P(GeneratedRandomPolygons, EveryCasePassesEveryProperty) {
  run_generated(CaseClass::RandomPolygons, GetParam(), kParts, {.normal = 100, .soak = 2000, .shrink_tries = 100});
}

INSTANTIATE_TEST_SUITE_P(Parts, GeneratedRandomPolygons, ::testing::Range<std::size_t>(0, kParts));

}  // namespace
}  // namespace procex::testing
