// Runs the procex executable as a child and gives its exit and its peak
// resident set (wait4's ru_maxrss): how tests see that a command's memory
// does not follow its input's size. Its standard output goes to /dev/null.
#pragma once

#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <fcntl.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

extern char** environ;

namespace procex::test {

// Peak RSS in KiB of `procex ARGS...`; a failure if it does not exit 0.
inline long procex_peak_kib(std::vector<std::string> args) {
  const std::string exe = PROCEX_CLI_EXE;
  args.insert(args.begin(), exe);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  rusage usage{};
  EXPECT_EQ(wait4(pid, &status, 0, &usage), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  return usage.ru_maxrss;
}

}  // namespace procex::test
