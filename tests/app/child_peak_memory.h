// Runs the procex executable as a child and gives its exit and its peak
// resident set (wait4's ru_maxrss): how tests see that a command's memory
// does not follow its input's size. Its standard output goes to /dev/null.
#pragma once

#include <sys/resource.h>
#include <sys/wait.h>

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "tests/app/spawn_procex.h"

namespace procex::test {

// Peak RSS in KiB of `procex ARGS...`; a failure if it does not exit 0.
inline long procex_peak_kib(std::vector<std::string> args) {
  const pid_t pid = spawn_procex(std::move(args));
  int status = 0;
  rusage usage{};
  EXPECT_EQ(wait4(pid, &status, 0, &usage), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  return usage.ru_maxrss;
}

}  // namespace procex::test
