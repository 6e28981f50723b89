// Node canvas geometry: the view transform, node boxes from declarations,
// pin and node hit tests, rubber-band selection and framing.
#include "app/studio/editor/canvas_layout.h"

#include <gtest/gtest.h>

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
