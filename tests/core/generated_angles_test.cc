// Class (b) of issue 12 item 2, per-edge angles, vertical edges, caps,
// profiles and plan edits on grid plans (tests/support/generators/): every
// case of the budget must pass every property check_case applies, and a
// failure is reported minimised, as a fixture to keep in tests/data. The
// class runs in parts, so that ctest spreads it over the cores.
#include <cstddef>

#include <gtest/gtest.h>

#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

constexpr std::size_t kParts = 8;

class GeneratedAngles : public ::testing::TestWithParam<std::size_t> {};

TEST_P(GeneratedAngles, EveryCasePassesEveryProperty) {
  run_generated(CaseClass::Angles, GetParam(), kParts, {.normal = 2000, .soak = 100000, .shrink_tries = 400});
}

INSTANTIATE_TEST_SUITE_P(Parts, GeneratedAngles, ::testing::Range<std::size_t>(0, kParts));

}  // namespace
}  // namespace procex::testing
