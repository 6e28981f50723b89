#include "graph/diagnostic.h"

namespace procex {

std::string to_string(const NodePath& path) {
  std::string s;
  for (NodeId id : path) {
    if (!s.empty()) s += '/';
    s += std::to_string(id);
  }
  return s;
}

std::string Diagnostic::to_string() const {
  std::string s = severity == Severity::kError ? "error: " : "warning: ";
  if (!node.empty()) {
    s += "node " + procex::to_string(node);
    if (!type.empty()) s += " (" + type + ")";
    s += ": ";
  }
  return s + message;
}

}  // namespace procex
