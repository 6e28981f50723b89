#include "app/cli/nodes_command.h"

#include <ostream>

#include "graph/registry.h"

namespace procex {

int run_nodes(const NodesCommandOptions& options, std::ostream& out) {
  const NodeRegistry& registry = NodeRegistry::global();
  if (options.markdown) {
    out << registry.markdown();
    return 0;
  }
  for (const auto& t : registry.all()) {
    const std::string& doc = t->decl.doc();
    const auto end = doc.find(". ");
    out << t->name() << " (" << t->decl.category() << ", v" << t->version() << "): "
        << (end == std::string::npos ? doc : doc.substr(0, end + 1)) << "\n";
  }
  return 0;
}

}  // namespace procex
