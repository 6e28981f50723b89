// Anchors in the plan editor without a window: placing one on an edge adds an
// Anchor node wired into the Extrude downstream, as one undo step; the
// sweep then resolves it there; positions convert between edge fractions and
// each mode's parameter.
#include "app/studio/editor/anchor_edit.h"

#include <gtest/gtest.h>

#include <chrono>

#include "app/studio/editor/eval_worker.h"
#include "graph/pxg.h"
#include "tests/studio/studio_test_util.h"

namespace procex::studio {
namespace {

using namespace std::chrono_literals;

const Value& param(const Document& doc, NodeId id, std::string_view name) {
  const Node* n = doc.graph().node(id);
  return n->params[*n->decl().param_index(name)];
}

// The house: Footprint Shape #1 -> Extrude #2 -> output.
std::unique_ptr<Document> house() { return Document::open(test::house_recipe()); }

TEST(AnchorEdit, PlacingAnAnchorAddsAWiredAnchorNodeAsOneUndoStep) {
  auto doc = house();
  doc->select_only(1);
  const std::string before = to_pxg(doc->graph());
  Result<NodeId> placed = place_anchor(*doc, 1, 2, 0.25);
  ASSERT_TRUE(placed) << placed.message();
  const NodeId a = *placed;
  EXPECT_EQ(doc->graph().node(a)->type->name(), "Anchor");
  EXPECT_EQ(param(*doc, a, "name").get<std::string>(), "anchor1");
  EXPECT_EQ(param(*doc, a, "mode").get<EnumValue>().choice, "fraction");
  EXPECT_EQ(param(*doc, a, "position").get<double>(), 0.25);
  EXPECT_EQ(param(*doc, a, "edges").get<std::string>(), "2");
  EXPECT_EQ(param(*doc, 2, "anchors").get<std::int64_t>(), 1);
  const auto input = doc->graph().node(2)->decl().input_index("anchor_1");
  ASSERT_TRUE(input);
  EXPECT_EQ(doc->graph().source(PortRef{2, static_cast<std::uint32_t>(*input)}), (PortRef{a, 0}));
  EXPECT_EQ(doc->selected(), 1u) << "the plan editor keeps the footprint";
  const std::vector<AnchorNode> listed = anchors_into(doc->graph(), 2);
  ASSERT_EQ(listed.size(), 1u);
  EXPECT_EQ(listed[0].edges, std::vector<std::int32_t>{2});

  // A second one: a new name and a new input.
  Result<NodeId> second = place_anchor(*doc, 1, 0, 0.5);
  ASSERT_TRUE(second) << second.message();
  EXPECT_EQ(param(*doc, *second, "name").get<std::string>(), "anchor2");
  EXPECT_EQ(param(*doc, 2, "anchors").get<std::int64_t>(), 2);
  EXPECT_EQ(anchors_into(doc->graph(), 2).size(), 2u);

  EXPECT_TRUE(doc->undo());
  EXPECT_TRUE(doc->undo());
  EXPECT_EQ(to_pxg(doc->graph()), before);
  EXPECT_TRUE(doc->redo());
  EXPECT_EQ(param(*doc, 2, "anchors").get<std::int64_t>(), 1);
  EXPECT_EQ(anchors_into(doc->graph(), 2).size(), 1u);
}

TEST(AnchorEdit, AFreeAnchorInputIsUsedBeforeAddingOne) {
  auto doc = house();
  ASSERT_TRUE(doc->set_port_count(2, *doc->graph().node(2)->decl().param_index("anchors"), 2));
  ASSERT_TRUE(place_anchor(*doc, 1, 1, 0.5));
  EXPECT_EQ(param(*doc, 2, "anchors").get<std::int64_t>(), 2);
}

TEST(AnchorEdit, RefusedWithoutAnExtrudeDownstreamAndNothingChanges) {
  auto doc = house();
  ASSERT_TRUE(doc->disconnect(PortRef{2, 0}));
  const std::string before = to_pxg(doc->graph());
  const std::string last_step = doc->undo_label();
  Result<NodeId> r = place_anchor(*doc, 1, 0, 0.5);
  ASSERT_FALSE(r);
  EXPECT_NE(r.message().find("no Extrude downstream"), std::string::npos) << r.message();
  EXPECT_EQ(to_pxg(doc->graph()), before);
  EXPECT_EQ(doc->undo_label(), last_step) << "no step recorded";
}

TEST(AnchorEdit, TheExtrudeIsFoundThroughNodesInBetween) {
  Document doc;
  const NodeId shape = *doc.add_node("Footprint Shape", 0, 0);
  const NodeId assign = *doc.add_node("Assign Profiles", 200, 0);
  const NodeId extrude = *doc.add_node("Extrude", 400, 0);
  ASSERT_TRUE(doc.connect({shape, 0}, {assign, 0}));
  ASSERT_TRUE(doc.connect({assign, 0}, {extrude, 0}));
  EXPECT_EQ(extrude_downstream(doc.graph(), shape), extrude);
  EXPECT_EQ(extrude_downstream(doc.graph(), extrude), extrude);
  EXPECT_FALSE(extrude_downstream(doc.graph(), 99));
}

TEST(AnchorEdit, ThePlacedAnchorResolvesOnTheClickedEdge) {
  auto doc = house();
  ASSERT_TRUE(place_anchor(*doc, 1, 0, 0.5));
  EvalWorker worker;
  worker.submit(doc->revision(), doc->graph());
  ASSERT_TRUE(worker.wait_idle(60s));
  const auto snap = worker.latest();
  ASSERT_TRUE(snap && snap->preview);
  ASSERT_EQ(snap->preview->anchors.size(), 1u);
  const ResolvedAnchor& r = snap->preview->anchors[0].anchor;
  EXPECT_EQ(r.name, "anchor1");
  EXPECT_EQ(r.edge_id, 0);
  EXPECT_TRUE(r.present) << r.reason;
  EXPECT_FALSE(snap->preview->marker_triangles.empty());
}

TEST(AnchorEdit, PositionsConvertBetweenFractionsAndEachMode) {
  EXPECT_DOUBLE_EQ(edge_fraction("fraction", 0.3, 10), 0.3);
  EXPECT_DOUBLE_EQ(edge_fraction("from_start", 2.5, 10), 0.25);
  EXPECT_DOUBLE_EQ(edge_fraction("from_end", 2.5, 10), 0.75);
  EXPECT_DOUBLE_EQ(edge_fraction("from_start", 25, 10), 1.0);  // past the end: at the end
  for (const char* mode : {"fraction", "from_start", "from_end"})
    EXPECT_NEAR(edge_fraction(mode, anchor_position(mode, 0.4, 8.0), 8.0), 0.4, 1e-12) << mode;
  EXPECT_DOUBLE_EQ(anchor_position("from_end", 1.5, 8.0), 0.0);  // dragged past the end: clamped
}

}  // namespace
}  // namespace procex::studio
