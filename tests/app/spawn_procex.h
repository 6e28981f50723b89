// Starts the procex executable as a child process, as a user would run it:
// how tests watch a command from outside (its open files, its peak memory,
// a signal part-way). Its standard output goes to /dev/null.
#pragma once

#include <spawn.h>
#include <sys/types.h>

#include <fcntl.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

extern char** environ;

namespace procex::test {

enum class ChildStderr { kKeep, kDiscard };

// The pid of `procex ARGS...`, with this process's environment but for the
// variables `env` sets ("NAME=value"); a failure if it cannot be started.
inline pid_t spawn_procex(std::vector<std::string> args, const std::vector<std::string>& env = {},
                          ChildStderr stderr_to = ChildStderr::kKeep) {
  const std::string exe = PROCEX_CLI_EXE;
  args.insert(args.begin(), exe);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  auto set_by_env = [&](const std::string& variable) {
    for (const std::string& e : env)
      if (variable.rfind(e.substr(0, e.find('=') + 1), 0) == 0) return true;
    return false;
  };
  std::vector<std::string> variables = env;
  for (char** e = environ; *e; ++e)
    if (!set_by_env(*e)) variables.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& v : variables) envp.push_back(v.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  if (stderr_to == ChildStderr::kDiscard) posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), envp.data()), 0) << exe;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

}  // namespace procex::test
