// node_canvas.h -- the node editor panel, drawn with ImGui draw lists.
//
// Draws the document's graph every frame (nodes from their declarations,
// links as bezier curves, error/warning badges, and cached/computed marks with
// each node's time under its box, from the last evaluation) and turns gestures into Document edits: drag from an
// output to an input to connect (refusals explained), drag a connected input
// away to disconnect, drag nodes to move them, click/ctrl-click/rubber band to
// select, right click or Tab for the searchable add menu, wheel to zoom,
// middle drag to pan, F to frame, L to lay the graph out, Delete, Ctrl+C / Ctrl+V / Ctrl+X, Ctrl+G to group,
// double-click or Enter on a group node to open it (its graph is then the one
// drawn and edited, under a breadcrumb bar whose steps back out), U to go up.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "app/studio/editor/canvas_layout.h"
#include "app/studio/editor/document.h"
#include "app/studio/editor/eval_worker.h"

namespace procex::studio {

class NodeCanvas {
 public:
  // `status` receives messages for the status bar (refused edits...).
  void draw(Document& doc, const EvalSnapshot* eval, std::string& status);
  // Frames all nodes on the next draw.
  void request_frame() { frame_pending_ = true; }
  // Whether node labels carry their evaluation time: a screenshot leaves it
  // out, so the same recipe gives the same picture on any machine.
  void show_times(bool on) { show_times_ = on; }

  // Where the last frame drew the canvas and its pins, in window pixels: the
  // --ui-map that tests driving real input events aim at.
  struct PinOnScreen {
    PortRef port;
    bool is_output = false;
    glm::vec2 pos{0.0f};
  };
  const std::vector<PinOnScreen>& pins_on_screen() const { return pins_on_screen_; }
  // The breadcrumb's steps (recipe, then each group entered), none at the recipe itself.
  const std::vector<Rect>& crumbs_on_screen() const { return crumbs_on_screen_; }
  Rect screen_rect() const { return screen_rect_; }
  // Each node's outcome and time of the shown evaluation, where the last frame wrote it.
  struct TimingOnScreen {
    NodeId node = 0;
    NodeOutcome outcome = NodeOutcome::kComputed;
    double ms = 0.0;
    Rect rect;
  };
  const std::vector<TimingOnScreen>& timings_on_screen() const { return timings_on_screen_; }
  float zoom() const { return view_.zoom; }
  // The canvas point at the middle of the panel: where nodes placed from elsewhere (the library) go.
  glm::vec2 view_centre() const { return view_.to_canvas((screen_rect_.min + screen_rect_.max) * 0.5f); }
  // The smallest text the last frame drew on the canvas, in pixels (0: none).
  float min_text_px() const { return min_text_px_; }
  // The zoom at which the canvas's text is kMinTextPx high.
  static float legible_zoom();

 private:
  void draw_add_menu(Document& doc, std::string& status);
  // "house.pxg > building > floor" above the canvas while inside a group.
  void breadcrumb(Document& doc);
  void open_group(Document& doc, NodeId id, std::string& status);

  CanvasView view_;
  bool frame_pending_ = true;
  bool show_times_ = true;
  // Gesture state (transient, not recipe data).
  enum class Drag { kNone, kNodes, kLink, kBand, kPan } drag_ = Drag::kNone;
  glm::vec2 drag_start_{0.0f};  // canvas units
  glm::vec2 drag_offset_{0.0f};
  PinHit link_from_{};
  glm::vec2 add_at_{0.0f};
  char search_[64] = {};
  int highlight_ = 0;    // the search list's entry that Enter places
  NodeId wire_from_ = 0;  // the node selected when the search opened: the new node is wired from it
  std::vector<NodeId> drawn_scope_;  // the group the last frame showed (Document::scope)
  std::vector<PinOnScreen> pins_on_screen_;
  std::vector<Rect> crumbs_on_screen_;
  std::vector<TimingOnScreen> timings_on_screen_;
  Rect screen_rect_;
  float min_text_px_ = 0.0f;
};

}  // namespace procex::studio
