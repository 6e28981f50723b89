// Class (a) of issue 12 item 2, exact grid and letter plans with one angle
// (tests/support/generators/): every case of the budget must pass every
// property check_case applies, and a failure is reported minimised, as a
// fixture to keep in tests/data. The class runs in parts, so that ctest
// spreads it over the cores. Class (b) is beside it; class (c), whose cases
// take CGAL up to a minute and gigabytes, is in tests/large.
#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

PROCEX_GENERATED_CLASS(GeneratedGrid, CaseClass::Grid, 8, {.normal = 2000, .soak = 100000, .shrink_tries = 400});

}  // namespace
}  // namespace procex::testing
