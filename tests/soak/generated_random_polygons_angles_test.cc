// Classes (b) and (c) of issue 12 together: random simple polygons of 8 to
// 1,000 vertices (random_simple_polygon) under class (b)'s per-edge angles,
// vertical edges, caps, profiles and plan edits. Walls leaning out over the
// polygons' pockets meet roofs there that grid plans, whose walls stand
// apart, do not make. Every case must pass every property check_case
// applies. Run by hand (ctest -L soak, or PROCEX_SOAK=1); TESTING.md records
// it.
#include <cstddef>

#include <gtest/gtest.h>

#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

constexpr std::size_t kParts = 4;

class GeneratedRandomPolygonsAngles : public ::testing::TestWithParam<std::size_t> {};

TEST_P(GeneratedRandomPolygonsAngles, EveryCasePassesEveryProperty) {
  run_generated(CaseClass::RandomPolygonsAngles, GetParam(), kParts, {.normal = 400, .soak = 10000, .shrink_tries = 200});
}

INSTANTIATE_TEST_SUITE_P(Parts, GeneratedRandomPolygonsAngles, ::testing::Range<std::size_t>(0, kParts));

}  // namespace
}  // namespace procex::testing
