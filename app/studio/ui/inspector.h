// inspector.h -- the selected node's parameters, drawn from its declaration:
// sliders with ranges and units for numbers, combos for enums, checkboxes,
// text for strings and tags, JSON text for anything else (lists, points).
// A drag of a slider is one undo step. A parameter that sets a port count
// (Merge inputs, Switch cases) gets - and + buttons. Also shows the node's documentation,
// its diagnostics and its last evaluation outcome. Right click on a parameter
// exposes it on the recipe's interface (name, label, range, default, unit) or
// unexposes it, and turns it into an expression (docs/expressions.md) or back
// into a value. An expression shows as its text in a tinted field with the
// value it gave in the last evaluation beside it; a refused one stays in the
// field with the reason under it, and the recipe keeps what it had. Inside a
// group, a parameter the group exposes has a note under it: its value there
// is only the group's default (editor/exposed_default.h).
#pragma once

#include <array>
#include <map>
#include <string>

#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"
#include "app/studio/ui/widget_rects.h"

namespace procex::studio {

class Inspector {
 public:
  void draw(Document& doc, const EvalSnapshot* eval, std::string& status);
  // Each parameter widget's rectangle in the last frame (window pixels), by
  // parameter name: part of the --ui-map for tests that click.
  const WidgetRects& widgets() const { return widgets_; }

 private:
  // Text being edited for string and JSON parameters, by "node.param", until committed.
  std::map<std::string, std::string> editing_;
  WidgetRects widgets_;
  void record(const std::string& name);  // the last item's rectangle into widgets_
  void expression_field(Document& doc, const EvalSnapshot* eval, NodeId id, std::size_t param, std::string& status);
  void expression_error(NodeId id, const ParamDecl& p);  // under the field, when the last edit was refused
  // Expression fields being edited, refused, or asked for but not yet set, by "node.param".
  struct ExpressionEdit {
    std::string text;
    std::string held;      // the node's expression when the edit began ("" for none): undo or redo drop the edit
    std::string initial;   // the text the field opened with
    std::string error;     // the last refusal, shown under the field
    bool focus = false;    // take the keyboard in the next frame
  };
  std::map<std::string, ExpressionEdit> expressions_;
  void expose_dialog(Document& doc, std::string& status);
  // The Expose dialog's fields, while it is open.
  struct Expose {
    bool open_requested = false;
    NodeId node = 0;
    std::size_t param = 0;
    std::string name, label, unit;
    bool numeric = false;
    double min = 0, max = 0, value = 0;
  } expose_;
};

}  // namespace procex::studio
