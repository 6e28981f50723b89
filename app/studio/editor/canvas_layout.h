// canvas_layout.h -- geometry of the node canvas, without a window: the view
// transform (pan, zoom), where each node and port sits, hit tests, framing.
// Node positions are the graph's editor state (canvas units); the pseudo
// nodes for graph inputs and outputs are placed beside the real nodes.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "graph/graph.h"

namespace procex::studio {

struct Rect {
  glm::vec2 min{0.0f}, max{0.0f};
  bool contains(glm::vec2 p) const { return p.x >= min.x && p.y >= min.y && p.x <= max.x && p.y <= max.y; }
  bool overlaps(const Rect& o) const { return min.x <= o.max.x && o.min.x <= max.x && min.y <= o.max.y && o.min.y <= max.y; }
  glm::vec2 size() const { return max - min; }
  bool operator==(const Rect&) const = default;
};

// Canvas units to screen pixels: screen = origin + (canvas + pan) * zoom.
struct CanvasView {
  glm::vec2 origin{0.0f};  // screen position of the canvas widget's corner
  glm::vec2 pan{0.0f};
  float zoom = 1.0f;

  glm::vec2 to_screen(glm::vec2 c) const { return origin + (c + pan) * zoom; }
  glm::vec2 to_canvas(glm::vec2 s) const { return (s - origin) / zoom - pan; }
  // Zooms by `factor` keeping the canvas point under `screen` fixed; zoom stays in [0.2, 3].
  void zoom_at(glm::vec2 screen, float factor);
  // Fits `bounds` (canvas units) into a widget of `size` pixels, with a
  // margin, centred. Never below `min_zoom` (the zoom at which text is still
  // legible): a graph too big for that shows its start (top left, where its
  // inputs are) and the rest is a scroll away.
  void frame(const Rect& bounds, glm::vec2 size, float min_zoom);
};

inline constexpr float kNodeWidth = 190.0f;
inline constexpr float kHeaderHeight = 24.0f;
inline constexpr float kRowHeight = 20.0f;
inline constexpr float kPinRadius = 5.0f;
// No text is drawn on the canvas below this height in pixels: farther out,
// nodes show their titles only (held at this size), then only boxes.
inline constexpr float kMinTextPx = 10.0f;
// Below this zoom a node's box is too narrow for a legible title.
inline constexpr float kTitleMinZoom = 0.4f;

// A node box's size, and where its pins sit below its top edge (canvas units).
glm::vec2 node_size(std::size_t inputs, std::size_t outputs);
inline float pin_offset(std::size_t port) { return kHeaderHeight + kRowHeight * (static_cast<float>(port) + 0.5f); }

struct NodeBox {
  NodeId id = 0;  // a node id, kGraphInputs or kGraphOutputs
  Rect rect;      // canvas units
  std::vector<glm::vec2> inputs, outputs;  // pin centres, canvas units
};

// Boxes of every node, then the graph input / output pseudo nodes when the
// graph has inputs / outputs.
std::vector<NodeBox> layout(const Graph& g);
const NodeBox* find_box(const std::vector<NodeBox>& boxes, NodeId id);

struct PinHit {
  PortRef port;
  bool is_output = false;
};
// The pin within `radius` canvas units of `p`, if any.
std::optional<PinHit> pin_at(const std::vector<NodeBox>& boxes, glm::vec2 p, float radius);
// The topmost real node (not a pseudo node) under `p`, or 0.
NodeId node_at(const std::vector<NodeBox>& boxes, glm::vec2 p);
// Real nodes overlapping `r` (a rubber-band selection).
std::vector<NodeId> nodes_in(const std::vector<NodeBox>& boxes, const Rect& r);
// Bounds of the given boxes (all when `ids` is empty).
Rect bounds(const std::vector<NodeBox>& boxes, const std::vector<NodeId>& ids = {});

// Space kept between a node placed by free_spot and every other box.
inline constexpr float kPlacementGap = 20.0f;
// The top-left corner for a new box of `size` whose centre is wanted at
// `centre`: there if the box would keep kPlacementGap from every box of
// `boxes` (nodes and the graph's input / output boxes), else the nearest
// such corner (searched on a grid of kPlacementGap) -- a node placed from
// elsewhere (the library) never covers another.
glm::vec2 free_spot(const std::vector<NodeBox>& boxes, glm::vec2 centre, glm::vec2 size);

}  // namespace procex::studio
