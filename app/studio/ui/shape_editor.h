// shape_editor.h -- the plan and profile editors (paper section 3, fig. 4):
// a 2D view of the selected node's footprint or profile.
//
// Plan: the evaluated footprint of the selected node, edges labelled with
// their id and angle or profile; click edges to select them (Assign
// Profiles' `selection` can take them). When the node's plan comes from a
// `points` parameter (Footprint Polygon), drag vertices, double-click an
// edge to add one, right-click a vertex to delete it.
// Profile: a Profile node's `points` polyline in (offset, height), segments
// labelled with their tags; dragging keeps it monotone and (0, 0) fixed.
// Every change is a set_param on the document, one undo step per drag.
#pragma once

#include <optional>
#include <set>
#include <string>

#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"

namespace procex::studio {

class ShapeEditor {
 public:
  void draw(Document& doc, const EvalSnapshot* eval, std::string& status);

 private:
  NodeId node_ = 0;
  std::optional<std::size_t> dragging_;
  std::set<std::int32_t> selected_edges_;  // edge ids of the footprint
};

}  // namespace procex::studio
