// Class (b) of issue 12 item 2, per-edge angles, vertical edges, caps,
// profiles and plan edits on grid plans (tests/support/generators/): every
// case of the budget must pass every property check_case applies, and a
// failure is reported minimised, as a fixture to keep in tests/data. The
// class runs in parts, so that ctest spreads it over the cores.
#include "tests/support/generators/run_generated.h"

namespace procex::testing {
namespace {

PROCEX_GENERATED_CLASS(GeneratedAngles, CaseClass::Angles, 8, {.normal = 2000, .soak = 100000, .shrink_tries = 400});

}  // namespace
}  // namespace procex::testing
