// `procex validate RECIPE`: loads and type-checks a recipe and reports its
// problems without evaluating any node.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <vector>

namespace procex {

struct ValidateCommandOptions {
  std::filesystem::path recipe;
  std::vector<std::filesystem::path> allowed_paths;  // --allow-path: folders besides the recipe's its files may lie in
};

// Inputs without a default are noted (batch binds them), not counted as problems.
// 0: no problems (warnings allowed); 1: structural problems;
// 2: the file cannot be loaded.
int run_validate(const ValidateCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
