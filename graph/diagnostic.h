// diagnostic.h -- messages attached to the node that raised them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace procex {

using NodeId = std::uint32_t;

// Where a node sits: its id in the recipe, then its id inside each group
// instance on the way down ("12/3" is node 3 inside group node 12).
using NodePath = std::vector<NodeId>;
std::string to_string(const NodePath& path);

enum class Severity { kWarning, kError };

struct Diagnostic {
  Severity severity = Severity::kError;
  NodePath node;         // empty for problems of the graph as a whole
  std::string type;      // the node's type name, for messages
  std::string message;   // for the user: what is wrong, and a hint where possible

  // "error: node 12/3 (Offset): distance makes the footprint vanish"
  std::string to_string() const;
};

}  // namespace procex
