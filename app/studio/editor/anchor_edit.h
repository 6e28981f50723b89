// anchor_edit.h -- anchors in the plan editor (paper 3.4, fig. 29): Anchor
// nodes feeding the Extrude downstream of the edited footprint, placed on a
// clicked edge and dragged along it. The anchor stays a node of the graph:
// these turn gestures into commands on the document.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/studio/editor/document.h"

namespace procex::studio {

// The first Extrude reached from `from`'s outputs by following links
// (breadth first; `from` itself when it is one).
std::optional<NodeId> extrude_downstream(const Graph& g, NodeId from);

// An Anchor node wired into an Extrude, as the plan editor draws it.
struct AnchorNode {
  NodeId node = 0;
  std::string name;
  std::string mode;               // "fraction", "from_start" or "from_end"
  double position = 0.5;
  std::string profile;            // only edges with this profile ("": any)
  std::vector<std::int32_t> edges;  // only these edge ids (empty: every edge); unreadable text reads as empty
};
std::vector<AnchorNode> anchors_into(const Graph& g, NodeId extrude);

// Where along an edge of length `length` (0 at its start, 1 at its end) an
// anchor of `mode` at `position` sits, clamped to the edge; and back.
double edge_fraction(const std::string& mode, double position, double length);
double anchor_position(const std::string& mode, double fraction, double length);

// Adds an Anchor node (mode fraction at `fraction` of edge `edge_id`, a name
// no other Anchor node has) and wires it into the Extrude downstream of
// `footprint_node`, on a free anchor input or a new one: one undo step, or
// nothing changed and the reason. The selection stays on `footprint_node`.
Result<NodeId> place_anchor(Document& doc, NodeId footprint_node, std::int32_t edge_id, double fraction);

}  // namespace procex::studio
