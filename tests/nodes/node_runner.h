// Runs one node type on given inputs and parameters, through a real graph and
// evaluator, so tests see exactly what a recipe would.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "graph/evaluator.h"

namespace procex::test {

struct NodeRun {
  std::vector<Value> outputs;  // empty values for failed outputs
  std::vector<Diagnostic> diagnostics;
  bool ok() const;
  std::string messages() const;  // every diagnostic, one per line
};

// inputs: by input name (unlisted optional inputs stay unconnected); relative
// file paths in parameters resolve against folder (EvalOptions::folder).
NodeRun run_node(const std::string& type, const std::map<std::string, Value>& params,
                 const std::map<std::string, Value>& inputs = {}, const std::filesystem::path& folder = {});

// A recipe's output "mesh", evaluated with a fresh cache; relative file paths
// in parameters resolve against folder.
EvalResult evaluate_mesh(const Graph& g, const std::filesystem::path& folder);

}  // namespace procex::test
