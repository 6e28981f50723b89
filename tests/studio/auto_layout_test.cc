// Auto-layout: nodes without positions are laid out in layers from inputs to
// outputs, without overlaps and with no more crossings than the samples'
// hand-made layouts; placed nodes stay put; "Tidy layout" is one undo step.
#include "app/studio/editor/auto_layout.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/studio/editor/canvas_layout.h"
#include "app/studio/editor/document.h"
#include "graph/pxg.h"
#include "studio_test_util.h"

namespace procex::studio {
namespace {

namespace fs = std::filesystem;

std::map<NodeId, glm::vec2> corners_of(const Graph& g) {
  std::map<NodeId, glm::vec2> out;
  for (const auto& [id, n] : g.nodes()) out[id] = {static_cast<float>(n.editor.x), static_cast<float>(n.editor.y)};
  return out;
}

void forget_positions(Graph& g) {
  for (const auto& [id, n] : std::map<NodeId, Node>(g.nodes())) ASSERT_TRUE(g.set_editor_state(id, EditorState{}));
}

void expect_readable(const Graph& g, const std::string& what) {
  const std::vector<NodeBox> boxes = layout(g);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      if (boxes[i].id > kMaxNodeId || boxes[j].id > kMaxNodeId) continue;
      EXPECT_FALSE(boxes[i].rect.overlaps(boxes[j].rect)) << what << ": nodes " << boxes[i].id << " and " << boxes[j].id << " overlap";
    }
  }
  for (const auto& [to, from] : g.links()) {
    if (from.node > kMaxNodeId || to.node > kMaxNodeId) continue;
    EXPECT_LT(g.node(from.node)->editor.x + kNodeWidth, g.node(to.node)->editor.x) << what << ": link " << from.node << " -> " << to.node << " runs backwards";
  }
}

TEST(AutoLayout, EverySampleLaidOutFromScratchIsLayeredAndNoWorseThanByHand) {
  std::size_t recipes = 0;
  for (const auto& entry : fs::directory_iterator(PROCEX_SAMPLES)) {
    if (entry.path().extension() != ".pxg") continue;
    Graph g = load_pxg(entry.path());
    const std::size_t by_hand = crossings(g, corners_of(g));
    forget_positions(g);
    ASSERT_EQ(stacked_nodes(g).size(), g.nodes().size());
    EXPECT_EQ(place_stacked_nodes(g), g.nodes().size());
    EXPECT_TRUE(stacked_nodes(g).empty());
    expect_readable(g, entry.path().filename().string());
    EXPECT_LE(crossings(g, corners_of(g)), by_hand) << entry.path().filename();
    ++recipes;
  }
  EXPECT_GE(recipes, 10u);
}

// A chain whose links cross when drawn in id order: the sweeps uncross them.
TEST(AutoLayout, ReducesCrossings) {
  Graph g;
  const NodeId a = *g.add_node("test.Const"), b = *g.add_node("test.Const");
  const NodeId sum1 = *g.add_node("test.Add"), sum2 = *g.add_node("test.Add");
  // a feeds the lower input of sum2 and b the upper of sum1 and lower of sum2...
  ASSERT_TRUE(g.connect({a, 0}, {sum2, 1}));
  ASSERT_TRUE(g.connect({b, 0}, {sum1, 0}));
  ASSERT_TRUE(g.connect({a, 0}, {sum1, 1}));
  ASSERT_TRUE(g.connect({b, 0}, {sum2, 0}));
  const NodeId last = *g.add_node("test.Add");
  ASSERT_TRUE(g.connect({sum2, 0}, {last, 0}));
  ASSERT_TRUE(g.connect({sum1, 0}, {last, 1}));
  const auto corners = layered_layout(g);
  EXPECT_EQ(corners.size(), 5u);
  EXPECT_EQ(corners.at(a).x, corners.at(b).x);
  EXPECT_GT(corners.at(sum1).x, corners.at(a).x);
  EXPECT_GT(corners.at(last).x, corners.at(sum1).x);
  // Four links between the first two layers: at best one crossing of a and b's pair into two adds.
  EXPECT_LE(crossings(g, corners), 1u);
}

TEST(AutoLayout, PlacedNodesStayWhereTheyAre) {
  Graph g = load_pxg(test::house_recipe());
  const NodeId extra1 = *g.add_node("Transform"), extra2 = *g.add_node("Transform");
  ASSERT_TRUE(g.connect({extra1, 0}, {extra2, 0}));
  const auto before = corners_of(g);
  // Node 1 of the house sits at (0, 0), where new nodes start: it keeps its place.
  ASSERT_EQ(g.node(1)->editor.x, 0.0);
  EXPECT_EQ(stacked_nodes(g), (std::vector<NodeId>{1, extra1, extra2}));
  EXPECT_EQ(place_stacked_nodes(g), 2u);
  for (const auto& [id, c] : before) {
    if (id == extra1 || id == extra2) continue;
    EXPECT_EQ(corners_of(g).at(id), c) << "node " << id;
  }
  expect_readable(g, "house plus two");
}

TEST(AutoLayout, ARecipeWithoutPositionsOpensLaidOutAndTidyIsOneUndoStep) {
  const fs::path dir = test::temp_dir();
  Graph g = load_pxg(fs::path(PROCEX_SAMPLES) / "bay_windows.pxg");
  forget_positions(g);
  // Written by hand: no editor block at all.
  nlohmann::json j = nlohmann::json::parse(to_pxg(g));
  j.erase("editor");
  std::ofstream(dir / "bare.pxg") << j.dump(2);
  auto doc = Document::open(dir / "bare.pxg");
  EXPECT_TRUE(stacked_nodes(doc->graph()).empty());
  EXPECT_FALSE(doc->dirty());
  expect_readable(doc->graph(), "bare.pxg");
  const NodeId first = doc->graph().nodes().begin()->first;
  doc->select_only(first);
  ASSERT_TRUE(doc->move_selection(500, 300));
  const auto moved = corners_of(doc->graph());
  ASSERT_TRUE(doc->tidy_layout());
  expect_readable(doc->graph(), "tidied");
  EXPECT_NE(corners_of(doc->graph()), moved);
  ASSERT_TRUE(doc->undo());
  EXPECT_EQ(corners_of(doc->graph()), moved);
}

}  // namespace
}  // namespace procex::studio
