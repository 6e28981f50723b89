#include "app/studio/editor/exposed_default.h"

#include <algorithm>

#include "graph/commands.h"

namespace procex::studio {

std::string exposed_default_note(const Document& doc, NodeId node, std::size_t param) {
  if (doc.scope().empty()) return "";
  const auto& exposed = doc.graph().exposed_params();
  const auto it = std::find_if(exposed.begin(), exposed.end(), [&](const ExposedParam& e) { return e.node == node && e.param == param; });
  if (it == exposed.end()) return "";
  // The instances are the nodes of the group in the graph that holds the group node entered last.
  const Result<std::vector<const Graph*>> levels = group_levels(doc.recipe(), doc.scope(), false);
  if (!levels) return "";
  const Graph& outer = *levels.value()[levels.value().size() - 2];
  const std::string& group = outer.node(doc.scope().back())->group;
  const auto instances = std::count_if(outer.nodes().begin(), outer.nodes().end(), [&](const auto& n) { return n.second.group == group; });
  const std::string how = instances == 1 ? "its instance keeps its own value: set '" + it->name + "' on the '" + group + "' node"
                                         : "its " + std::to_string(instances) + " instances keep their own values: set '" + it->name +
                                               "' on each '" + group + "' node";
  return "Exposed as '" + it->name + "': here only the group's default (for new instances); " + how + ".";
}

}  // namespace procex::studio
