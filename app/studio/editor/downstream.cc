#include "app/studio/editor/downstream.h"

#include <deque>
#include <set>

namespace procex::studio {

std::vector<NodeId> downstream_of_type(const Graph& g, NodeId from, std::string_view type) {
  std::vector<NodeId> found;
  std::deque<NodeId> queue = {from};
  std::set<NodeId> seen = {from};
  while (!queue.empty()) {
    const NodeId id = queue.front();
    queue.pop_front();
    const Node* n = g.node(id);
    if (!n) continue;
    if (n->type->name() == type) found.push_back(id);
    for (const Link& l : g.links_from(id))
      if (l.to.node != kGraphOutputs && seen.insert(l.to.node).second) queue.push_back(l.to.node);
  }
  return found;
}

}  // namespace procex::studio
