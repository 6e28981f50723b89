// downstream.h -- which nodes an edit reaches: the editors look for the nodes
// of a type fed, directly or not, by the node being edited (the Extrude that
// resolves a footprint's anchors, the Profile Offsets that step a profile).
#pragma once

#include <string_view>
#include <vector>

#include "graph/graph.h"

namespace procex::studio {

// Nodes of type `type` reached from `from` by following links (breadth first,
// nearest first; `from` itself when it is one).
std::vector<NodeId> downstream_of_type(const Graph& g, NodeId from, std::string_view type);

}  // namespace procex::studio
