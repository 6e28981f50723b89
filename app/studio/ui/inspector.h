// inspector.h -- the selected node's parameters, drawn from its declaration:
// sliders with ranges and units for numbers, combos for enums, checkboxes,
// text for strings and tags, JSON text for anything else (lists, points).
// A drag of a slider is one undo step. Also shows the node's documentation,
// its diagnostics and its last evaluation outcome.
#pragma once

#include <map>
#include <string>

#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"

namespace procex::studio {

class Inspector {
 public:
  void draw(Document& doc, const EvalSnapshot* eval, std::string& status);

 private:
  // Text being edited for string and JSON parameters, by "node.param", until committed.
  std::map<std::string, std::string> editing_;
};

}  // namespace procex::studio
