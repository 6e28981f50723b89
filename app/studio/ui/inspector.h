// inspector.h -- the selected node's parameters, drawn from its declaration:
// sliders with ranges and units for numbers, combos for enums, checkboxes,
// text for strings and tags, JSON text for anything else (lists, points).
// A drag of a slider is one undo step. A parameter that sets a port count
// (Merge inputs, Switch cases) gets - and + buttons. Also shows the node's documentation,
// its diagnostics and its last evaluation outcome.
#pragma once

#include <array>
#include <map>
#include <string>

#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"

namespace procex::studio {

class Inspector {
 public:
  void draw(Document& doc, const EvalSnapshot* eval, std::string& status);
  // Each parameter widget's rectangle in the last frame (window pixels), by
  // parameter name: part of the --ui-map for tests that click.
  const std::map<std::string, std::array<float, 4>>& widgets() const { return widgets_; }

 private:
  // Text being edited for string and JSON parameters, by "node.param", until committed.
  std::map<std::string, std::string> editing_;
  std::map<std::string, std::array<float, 4>> widgets_;
};

}  // namespace procex::studio
