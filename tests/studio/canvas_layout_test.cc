// Node canvas geometry: the view transform, node boxes from declarations,
// pin and node hit tests, rubber-band selection and framing.
#include "app/studio/editor/canvas_layout.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <glm/geometric.hpp>

#include "app/studio/editor/document.h"

namespace procex::studio {
namespace {

TEST(CanvasView, ScreenAndCanvasAreInverse) {
  CanvasView v;
  v.origin = {100, 50};
  v.pan = {-30, 12};
  v.zoom = 1.7f;
  const glm::vec2 c(42, -7);
  const glm::vec2 back = v.to_canvas(v.to_screen(c));
  EXPECT_NEAR(back.x, c.x, 1e-4);
  EXPECT_NEAR(back.y, c.y, 1e-4);
}

TEST(CanvasView, ZoomKeepsThePointUnderTheMouse) {
  CanvasView v;
  v.origin = {10, 10};
  const glm::vec2 mouse(300, 200);
  const glm::vec2 before = v.to_canvas(mouse);
  v.zoom_at(mouse, 1.5f);
  EXPECT_FLOAT_EQ(v.zoom, 1.5f);
  const glm::vec2 after = v.to_canvas(mouse);
  EXPECT_NEAR(after.x, before.x, 1e-3);
  EXPECT_NEAR(after.y, before.y, 1e-3);
  v.zoom_at(mouse, 100.0f);
  EXPECT_FLOAT_EQ(v.zoom, 3.0f);  // clamped
}

TEST(CanvasView, FrameFitsAndCentresTheBounds) {
  CanvasView v;
  v.origin = {0, 0};
  const Rect r{{-500, 100}, {1500, 600}};
  v.frame(r, {800, 400}, 0.2f);
  const glm::vec2 a = v.to_screen(r.min), b = v.to_screen(r.max);
  EXPECT_GE(a.x, 0);
  EXPECT_GE(a.y, 0);
  EXPECT_LE(b.x, 800);
  EXPECT_LE(b.y, 400);
  EXPECT_NEAR((a.x + b.x) / 2, 400, 1e-2);
  EXPECT_NEAR((a.y + b.y) / 2, 200, 1e-2);
}

// A graph too big to fit at a legible zoom keeps the legible zoom and shows its top-left corner.
TEST(CanvasView, FrameNeverShrinksTextBelowTheLegibleZoom) {
  CanvasView v;
  v.origin = {10, 20};
  const Rect r{{-500, 100}, {1500, 600}};
  v.frame(r, {800, 400}, 0.8f);
  EXPECT_FLOAT_EQ(v.zoom, 0.8f);
  const glm::vec2 a = v.to_screen(r.min);
  EXPECT_NEAR(a.x, 10 + 40, 1e-2);
  EXPECT_NEAR(a.y, 20 + 40, 1e-2);
  // One that fits is centred as before.
  v.frame(Rect{{0, 0}, {300, 100}}, {800, 400}, 0.8f);
  EXPECT_FLOAT_EQ(v.zoom, 1.5f);
  EXPECT_NEAR(v.to_screen({150, 50}).x, 10 + 400, 1e-2);
}

TEST(Layout, BoxesFollowDeclarationsAndEditorPositions) {
  Document doc;
  NodeId add = *doc.add_node("test.Add", 100, 40);  // inputs a, b; output sum
  const auto boxes = layout(doc.graph());
  ASSERT_EQ(boxes.size(), 1u);
  const NodeBox& b = boxes[0];
  EXPECT_EQ(b.id, add);
  EXPECT_EQ(b.rect.min, glm::vec2(100, 40));
  ASSERT_EQ(b.inputs.size(), 2u);
  ASSERT_EQ(b.outputs.size(), 1u);
  EXPECT_EQ(b.inputs[0].x, 100);
  EXPECT_EQ(b.outputs[0].x, 100 + kNodeWidth);
  EXPECT_LT(b.inputs[0].y, b.inputs[1].y);
  // Pins are hit near their centre; node bodies elsewhere.
  auto pin = pin_at(boxes, b.inputs[1] + glm::vec2(2, -2), 6);
  ASSERT_TRUE(pin);
  EXPECT_EQ(pin->port, (PortRef{add, 1}));
  EXPECT_FALSE(pin->is_output);
  pin = pin_at(boxes, b.outputs[0], 6);
  ASSERT_TRUE(pin);
  EXPECT_TRUE(pin->is_output);
  EXPECT_FALSE(pin_at(boxes, b.rect.min + glm::vec2(80, 10), 6));
  EXPECT_EQ(node_at(boxes, b.rect.min + glm::vec2(80, 10)), add);
  EXPECT_EQ(node_at(boxes, b.rect.max + glm::vec2(5, 5)), 0u);
}

TEST(Layout, GraphOutputsSitRightOfTheNodesAndAreNeverSelected) {
  Graph g;
  ASSERT_TRUE(g.add_output({"result", &value_type<double>(), ""}));
  ASSERT_TRUE(g.add_node("test.Const"));
  const auto boxes = layout(g);
  ASSERT_EQ(boxes.size(), 2u);
  const NodeBox* out = find_box(boxes, kGraphOutputs);
  ASSERT_TRUE(out);
  EXPECT_GT(out->rect.min.x, find_box(boxes, 1)->rect.max.x);
  EXPECT_EQ(out->inputs.size(), 1u);
  EXPECT_EQ(node_at(boxes, out->rect.min + glm::vec2(5, 5)), 0u);
  EXPECT_EQ(nodes_in(boxes, bounds(boxes)), std::vector<NodeId>{1});
}

// Whether `r` keeps at least kPlacementGap from `o` along some axis.
bool apart(const Rect& r, const Rect& o) {
  return r.max.x + kPlacementGap <= o.min.x || o.max.x + kPlacementGap <= r.min.x || r.max.y + kPlacementGap <= o.min.y ||
         o.max.y + kPlacementGap <= r.min.y;
}

// Where a node placed from elsewhere (the library) goes: centred where it is
// wanted when that is free, else at the nearest grid point from which it keeps
// the gap from every box, the graph's input and output boxes included.
TEST(Layout, FreeSpotIsTheWantedOneOrTheNearestThatCoversNoBox) {
  const glm::vec2 size = node_size(2, 1);
  EXPECT_EQ(free_spot({}, {100, 100}, size), glm::vec2(100, 100) - size * 0.5f);

  // A block of 4 x 4 nodes packed with exactly the gap between them, and an output box beside it.
  Graph g;
  ASSERT_TRUE(g.add_output({"result", &value_type<double>(), ""}));
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) {
      const Result<NodeId> id = g.add_node("test.Const");
      ASSERT_TRUE(id);
      EditorState e;
      e.x = col * (kNodeWidth + kPlacementGap);
      e.y = row * (node_size(0, 1).y + kPlacementGap);
      ASSERT_TRUE(g.set_editor_state(*id, e));
    }
  const std::vector<NodeBox> boxes = layout(g);
  ASSERT_EQ(boxes.size(), 17u);
  std::vector<NodeId> nodes;
  for (const auto& [id, n] : g.nodes()) nodes.push_back(id);
  const Rect block = bounds(boxes, nodes);
  for (const NodeBox& wanted_on : boxes) {
    const glm::vec2 centre = (wanted_on.rect.min + wanted_on.rect.max) * 0.5f;
    const glm::vec2 corner = free_spot(boxes, centre, size);
    const Rect placed{corner, corner + size};
    for (const NodeBox& b : boxes) EXPECT_TRUE(apart(placed, b.rect)) << "wanted on node " << b.id << ", placed at " << corner.x << ", " << corner.y;
    // No grid point nearer the wanted corner is free.
    const glm::vec2 want = centre - size * 0.5f;
    const float d2 = glm::dot(corner - want, corner - want);
    for (int i = -60; i <= 60; ++i)
      for (int j = -60; j <= 60; ++j) {
        const glm::vec2 c = want + glm::vec2(i, j) * kPlacementGap;
        if (glm::dot(c - want, c - want) >= d2) continue;
        const Rect r{c, c + size};
        EXPECT_FALSE(std::all_of(boxes.begin(), boxes.end(), [&](const NodeBox& b) { return apart(r, b.rect); }))
            << "a nearer free spot at " << c.x << ", " << c.y;
      }
  }
  // Within the block of nodes nothing is free: wanted at its middle, a node goes outside it.
  const glm::vec2 corner = free_spot(boxes, (block.min + block.max) * 0.5f, size);
  EXPECT_FALSE(Rect({corner, corner + size}).overlaps(block));
}

TEST(Layout, RubberBandSelectsOverlappingNodes) {
  Document doc;
  NodeId a = *doc.add_node("test.Const", 0, 0);
  NodeId b = *doc.add_node("test.Const", 400, 0);
  NodeId c = *doc.add_node("test.Const", 0, 300);
  const auto boxes = layout(doc.graph());
  EXPECT_EQ(nodes_in(boxes, Rect{{-10, -10}, {450, 20}}), (std::vector<NodeId>{a, b}));
  EXPECT_EQ(nodes_in(boxes, Rect{{-10, 250}, {20, 320}}), (std::vector<NodeId>{c}));
  const Rect all = bounds(boxes);
  EXPECT_EQ(all.min, glm::vec2(0, 0));
  EXPECT_EQ(all.max.x, 400 + kNodeWidth);
  const Rect only_c = bounds(boxes, {c});
  EXPECT_EQ(only_c.min, glm::vec2(0, 300));
}

}  // namespace
}  // namespace procex::studio
