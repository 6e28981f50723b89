// Runs the procex executable as a child and gives its exit and its peak
// resident set (wait4's ru_maxrss): how tests see that a command's memory
// does not follow its input's size. Its standard output goes to /dev/null.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tests/app/spawn_procex.h"
#include "tests/support/child_peak_memory.h"

namespace procex::test {

// Peak RSS in KiB of `procex ARGS...`; a failure if it does not exit 0.
inline long procex_peak_kib(std::vector<std::string> args) { return child_peak_kib(spawn_procex(std::move(args))); }

}  // namespace procex::test
