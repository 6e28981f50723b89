// The peak resident set of a child process once it has exited (wait4's
// ru_maxrss): how tests see that memory does not follow an input's size.
#pragma once

#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

namespace procex::test {

// Waits for `pid`; its peak RSS in KiB, and a failure if it does not exit 0.
inline long child_peak_kib(pid_t pid) {
  int status = 0;
  rusage usage{};
  EXPECT_EQ(wait4(pid, &status, 0, &usage), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  return usage.ru_maxrss;
}

}  // namespace procex::test
