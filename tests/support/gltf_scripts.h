// Runs the Node.js checks of tools/ on a .glb (as installed by
// scripts/install-deps.sh) and hands back the JSON they print: the Khronos
// glTF validator (validate_gltf.mjs) and three.js's loader (*_three.mjs).
// A missing tool is a problem the caller fails on, never a skip.
#pragma once

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace procex::test {

struct NodeScriptRun {
  std::string problem;        // why there is no report ("" when there is one)
  int exit_code = -1;         // 0 without errors, 1 with errors
  nlohmann::json report;      // what the script printed
};

// script: a file of tools/, e.g. "validate_gltf.mjs" (its report: {"issues": {...}, "info": {...}}).
inline NodeScriptRun run_gltf_script(const std::string& script, const std::filesystem::path& glb) {
  const std::filesystem::path tools = std::filesystem::path(PROCEX_SAMPLES).parent_path() / "tools";
  NodeScriptRun v;
  const auto run = [](const std::string& command, std::string& out) {
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return -1;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
    const int status = ::pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  std::string out;
  if (run("node --version", out) != 0) {
    v.problem = "node (Node.js) is not installed: run scripts/install-deps.sh";
    return v;
  }
  if (!std::filesystem::exists(tools / "node_modules" / "gltf-validator") ||
      !std::filesystem::exists(tools / "node_modules" / "three")) {
    v.problem = "run scripts/install-deps.sh (or: cd tools && npm ci) to install the glTF validator and three.js";
    return v;
  }
  out.clear();
  v.exit_code = run("node " + (tools / script).string() + " " + glb.string(), out);
  try {
    v.report = nlohmann::json::parse(out);
  } catch (const nlohmann::json::exception&) {
    v.problem = script + " printed no JSON: " + out;
  }
  return v;
}

}  // namespace procex::test
