// auto_layout.h -- places nodes in layers from inputs to outputs (a
// Sugiyama-style layered drawing: layering by longest path, long links
// broken into chains of dummy points, crossings reduced by barycenter sweeps
// over port positions, then rows aligned with their neighbours).
//
// Used for recipes written by hand or by scripts, whose nodes have no
// positions (every node stacked on one spot), and for "Tidy layout".
#pragma once

#include <map>
#include <vector>

#include <glm/vec2.hpp>

#include "graph/graph.h"

namespace procex::studio {

// Top-left corners (canvas units) for every real node of `g`.
std::map<NodeId, glm::vec2> layered_layout(const Graph& g);

// Link crossings of a drawing with the given corners (links as straight
// segments between pins; a measure for tests and for choosing orders).
std::size_t crossings(const Graph& g, const std::map<NodeId, glm::vec2>& corners);

// Nodes that share their position with another node: written without an
// editor block, they would all sit on one spot.
std::vector<NodeId> stacked_nodes(const Graph& g);

// Gives the stacked nodes positions: the first node on each spot stays (it
// may have been put there); the whole graph is laid out when more than half
// the nodes need places, otherwise those are laid out among themselves below
// the placed ones. Editor state only: no hash changes. Returns how many moved.
std::size_t place_stacked_nodes(Graph& g);

}  // namespace procex::studio
