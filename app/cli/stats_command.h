// `procex stats RECIPE [--set name=value ...]`: evaluates a recipe twice and
// prints per-node time, outcome (computed, cache hit, pass-through...) and
// memory for the cold run, then what the cache saved on the warm one.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace procex {

struct StatsCommandOptions {
  std::filesystem::path recipe;
  std::vector<std::string> settings;
  std::vector<std::filesystem::path> allowed_paths;  // --allow-path: folders besides the recipe's its files may lie in
};

// 0, or 1 if a node failed, 2 if the recipe cannot be loaded.
int run_stats(const StatsCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace procex
