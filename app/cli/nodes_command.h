// `procex nodes [--markdown]`: the node types, from their declarations.
#pragma once

#include <iosfwd>

namespace procex {

struct NodesCommandOptions {
  bool markdown = false;  // full documentation; otherwise one line per type
};

int run_nodes(const NodesCommandOptions& options, std::ostream& out);

}  // namespace procex
