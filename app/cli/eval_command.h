// `procex eval RECIPE -o out.(obj|ply|glb) [--set name=value ...]`: evaluates
// a recipe's mesh outputs and writes them to one file (atomically).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace procex {

struct EvalCommandOptions {
  std::filesystem::path recipe;
  std::filesystem::path output;       // .obj, .ply or .glb
  std::vector<std::string> settings;  // name=value: exposed parameters or graph inputs
};

// 0: written; 1: a node failed (diagnostics on err, nothing written);
// 2: the recipe cannot be loaded, a setting is wrong, or the output cannot be written.
int run_eval(const EvalCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
