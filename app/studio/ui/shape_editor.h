// shape_editor.h -- the plan and profile editors (paper section 3, fig. 4):
// a 2D view of the selected node's footprint or profile.
//
// Plan: the evaluated footprint of the selected node, edges labelled with
// their id and angle or profile; click edges to select them (Assign
// Profiles' `selection` can take them). When the node's plan comes from a
// `points` parameter (Footprint Polygon), drag vertices, double-click an
// edge to add one, right-click a vertex to delete it; the same for its holes,
// which Add hole / Delete hole make and remove (any number; Delete removes
// the hole whose corner was grabbed or whose name was clicked last). A plan core would refuse is
// flagged at the loop and vertex at fault. The anchors of Anchor nodes wired
// into the Extrude downstream are drawn on their edges and dragged along them
// (their `position`); with Place anchor on, a click on an edge adds one.
// Profile: a Profile node's `points` polyline in (offset, height), segments
// labelled with their tags (click a segment to edit its tag; adding and
// deleting points keeps one tag per segment); dragging keeps it monotone and (0, 0) fixed,
// and snaps a point level with a neighbour (a soffit or ledge) or plumb. The
// Profile Offsets the profile feeds show their step as a handle at
// (the profile's offset at `height` + `distance`, `height`); dragging it edits both.
// Every change is a set_param on the document, one undo step per drag.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"
#include "app/studio/editor/plan_edit.h"

namespace procex::studio {

class ShapeEditor {
 public:
  void draw(Document& doc, const EvalSnapshot* eval, std::string& status);
  // Buttons, profile segment midpoints (segment_K), plan edge midpoints
  // (edge_ID) and anchors (anchor_NODE_eID) drawn in the last frame (window
  // pixels), for the --ui-map.
  const std::map<std::string, std::array<float, 4>>& buttons() const { return buttons_; }
  // Place anchor is on: a click on an edge places one.
  bool anchor_tool() const { return anchor_tool_; }

 private:
  struct Grab {
    std::size_t loop = 0, point = 0;  // loop 0: the points, k: hole k (from 1)
    bool operator==(const Grab&) const = default;
  };
  NodeId node_ = 0;
  std::optional<Grab> dragging_;
  std::uint64_t check_revision_ = 0;  // the plan is checked again only after an edit
  std::optional<PlanIssue> issue_;
  std::map<std::string, std::array<float, 4>> buttons_;
  std::optional<std::size_t> selected_segment_;  // a profile segment whose tag is being edited
  std::size_t segment_tag_edit_ = SIZE_MAX;
  std::string segment_tag_;
  std::set<std::int32_t> selected_edges_;  // edge ids of the footprint
  struct AnchorDrag {
    NodeId node = 0;
    Vec2 a, b;  // the edge it slides along
  };
  std::optional<AnchorDrag> dragging_anchor_;
  bool anchor_tool_ = false;  // a click on an edge places an anchor
  std::optional<NodeId> dragging_offset_;  // a Profile Offset whose handle is dragged
  std::size_t active_hole_ = 0;  // the hole Delete hole removes (index into the holes)
};

}  // namespace procex::studio
