#include <gtest/gtest.h>

#include "graph/commands.h"
#include "graph/pxg.h"
#include "tests/graph/test_graphs.h"

namespace procex {
namespace {

// Undo must restore the graph exactly; the canonical file text is a complete fingerprint.
class Commands : public ::testing::Test {
 protected:
  void SetUp() override {
    d = test::diamond();
    original = to_pxg(d.g);
  }
  test::Diamond d;
  std::string original;
};

TEST_F(Commands, EveryCommandUndoesAndRedoesExactly) {
  UndoStack stack(d.g);
  std::vector<std::string> states{original};
  auto step = [&](Status s) {
    ASSERT_TRUE(s) << s.message();
    states.push_back(to_pxg(d.g));
  };
  auto added = stack.add_node("test.Switch", EditorState{5, 6, {}, false});
  ASSERT_TRUE(added);
  states.push_back(to_pxg(d.g));
  step(stack.connect(PortRef{d.mul, 0}, PortRef{*added, 0}));
  step(stack.set_param(*added, "enabled", Value::make(false)));
  step(stack.move(*added, 50, 60));
  step(stack.set_editor_state(d.c1, EditorState{0, 0, "one", true}));
  step(stack.disconnect(PortRef{d.add1, 1}));
  step(stack.remove_node(d.add2));
  auto inst = stack.group({d.c1, d.add1}, "left");
  ASSERT_TRUE(inst) << inst.message();
  states.push_back(to_pxg(d.g));

  for (std::size_t i = states.size() - 1; i > 0; --i) {
    ASSERT_TRUE(stack.undo());
    ASSERT_EQ(to_pxg(d.g), states[i - 1]) << "after undoing step " << i;
  }
  EXPECT_FALSE(stack.undo());
  for (std::size_t i = 1; i < states.size(); ++i) {
    ASSERT_TRUE(stack.redo());
    ASSERT_EQ(to_pxg(d.g), states[i]) << "after redoing step " << i;
  }
  EXPECT_FALSE(stack.redo());
}

TEST_F(Commands, RefusedEditsChangeNothingAndRecordNothing) {
  UndoStack stack(d.g);
  EXPECT_EQ(stack.add_node("test.Mull").message(), "unknown node type 'test.Mull'; did you mean 'test.Mul'?");
  EXPECT_FALSE(stack.connect(PortRef{d.mul, 0}, PortRef{d.c1, 0}));  // c1 has no inputs
  EXPECT_EQ(stack.connect(PortRef{d.mul, 0}, PortRef{d.add1, 0}).message(),
            "linking 7.product to 5.a would make a cycle: node 7 already depends on node 5");
  EXPECT_FALSE(stack.set_param(d.add1, "scale", Value::make(1e9)));
  EXPECT_FALSE(stack.remove_node(99));
  EXPECT_FALSE(stack.group({}, "empty"));
  EXPECT_FALSE(stack.can_undo());
  EXPECT_EQ(to_pxg(d.g), original);
}

TEST_F(Commands, ConnectReplacesAndUndoRestoresTheOldLink) {
  UndoStack stack(d.g);
  ASSERT_TRUE(stack.connect(PortRef{d.c4, 0}, PortRef{d.add1, 0}));
  EXPECT_EQ(d.g.source(PortRef{d.add1, 0}), (PortRef{d.c4, 0}));
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(d.g.source(PortRef{d.add1, 0}), (PortRef{d.c1, 0}));
}

TEST_F(Commands, DragsMergeIntoOneStep) {
  UndoStack stack(d.g);
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(stack.move(d.mul, i, i));
  stack.end_interaction();
  ASSERT_TRUE(stack.move(d.mul, 100, 100));
  EXPECT_EQ(d.g.node(d.mul)->editor.x, 100);
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(d.g.node(d.mul)->editor.x, 9);
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(d.g.node(d.mul)->editor.x, 0);
  EXPECT_FALSE(stack.can_undo());
}

TEST_F(Commands, MacrosAreOneStepAndCanBeAborted) {
  UndoStack stack(d.g);
  stack.begin_macro("paste");
  auto a = stack.add_node("test.Const");
  auto b = stack.add_node("test.Add");
  ASSERT_TRUE(a && b);
  ASSERT_TRUE(stack.connect(PortRef{*a, 0}, PortRef{*b, 0}));
  stack.end_macro();
  EXPECT_EQ(stack.undo_label(), "paste");
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(to_pxg(d.g), original);
  ASSERT_TRUE(stack.redo());
  EXPECT_EQ(d.g.nodes().size(), 9u);

  stack.begin_macro("half done");
  ASSERT_TRUE(stack.add_node("test.Const"));
  stack.abort_macro();
  EXPECT_EQ(d.g.nodes().size(), 9u);
  EXPECT_EQ(stack.undo_label(), "paste");
}

TEST_F(Commands, GroupingWiresTheBoundary) {
  UndoStack stack(d.g);
  ASSERT_TRUE(d.g.expose_param(ExposedParam{"left_scale", d.add1, 0}));
  auto inst = stack.group({d.c2, d.add1}, "left");
  ASSERT_TRUE(inst) << inst.message();
  const GroupDef& def = d.g.groups().at("left");
  const Graph& body = *def.type->body;
  ASSERT_EQ(body.inputs().size(), 1u);  // c1 -> add1.a crosses in
  EXPECT_EQ(body.inputs()[0].name, "a");
  ASSERT_EQ(body.outputs().size(), 1u);  // add1.sum -> mul.a crosses out
  EXPECT_EQ(body.outputs()[0].name, "sum");
  EXPECT_EQ(d.g.source(PortRef{*inst, 0}), (PortRef{d.c1, 0}));
  EXPECT_EQ(d.g.source(PortRef{d.mul, 0}), (PortRef{*inst, 0}));
  ASSERT_EQ(d.g.exposed_params().size(), 1u);
  EXPECT_EQ(d.g.exposed_params()[0].node, *inst);
  EXPECT_EQ(d.g.node(*inst)->decl().params()[0].name, "left_scale");
  EXPECT_EQ(stack.group({d.c3}, "left").message(), "there is already a group named 'left'");
}

TEST_F(Commands, UngroupRestoresTheWiringAndTheExposedValues) {
  UndoStack stack(d.g);
  ASSERT_TRUE(d.g.expose_param(ExposedParam{"left_scale", d.add1, 0}));
  auto inst = stack.group({d.c2, d.add1}, "left");
  ASSERT_TRUE(inst);
  ASSERT_TRUE(stack.set_param(*inst, "left_scale", Value::make(3.0)));
  const std::string grouped = to_pxg(d.g);
  auto created = stack.ungroup(*inst);
  ASSERT_TRUE(created) << created.message();
  ASSERT_EQ(created.value().size(), 2u);
  EXPECT_EQ(d.g.node(*inst), nullptr);
  const NodeId new_c2 = created.value()[0], new_add1 = created.value()[1];
  EXPECT_EQ(d.g.node(new_add1)->params[0].get<double>(), 3.0);
  EXPECT_EQ(d.g.source(PortRef{new_add1, 0}), (PortRef{d.c1, 0}));
  EXPECT_EQ(d.g.source(PortRef{new_add1, 1}), (PortRef{new_c2, 0}));
  EXPECT_EQ(d.g.source(PortRef{d.mul, 0}), (PortRef{new_add1, 0}));
  ASSERT_EQ(d.g.exposed_params().size(), 1u);
  EXPECT_EQ(d.g.exposed_params()[0].node, new_add1);
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(to_pxg(d.g), grouped);
  EXPECT_EQ(stack.ungroup(d.c1).message(), "node 1 is not a group instance");
}

// Edits made inside a group (UndoStack::set_scope) change the group for
// every instance of it, keep the instances' own values and links, and undo
// and redo exactly from any level; a nested group is reached through both.
TEST_F(Commands, EditsInsideAGroupChangeItForEveryInstanceAndUndoExactly) {
  UndoStack stack(d.g);
  ASSERT_TRUE(d.g.expose_param(ExposedParam{"left_scale", d.add1, 0}));
  const std::string exposed = to_pxg(d.g);
  const Result<NodeId> inst = stack.group({d.c2, d.add1}, "left");
  ASSERT_TRUE(inst) << inst.message();
  ASSERT_TRUE(stack.set_param(*inst, "left_scale", Value::make(3.0)));
  const Result<NodeId> other = stack.add_group_node("left");
  ASSERT_TRUE(other);
  std::vector<std::string> states{to_pxg(d.g)};
  auto step = [&](Status s) {
    ASSERT_TRUE(s) << s.message();
    states.push_back(to_pxg(d.g));
  };
  EXPECT_EQ(stack.set_scope({d.c1}).message(), "node 1 is not a group node");
  ASSERT_TRUE(stack.set_scope({*inst}));
  EXPECT_EQ(&stack.scoped(), d.g.node(*inst)->type->body.get());
  step(stack.set_param(d.c2, "value", Value::make(7.0)));
  const auto body = [&]() -> const Graph& { return *d.g.groups().at("left").type->body; };
  EXPECT_EQ(body().node(d.c2)->params[0].get<double>(), 7.0);
  EXPECT_EQ(d.g.node(*inst)->type, d.g.groups().at("left").type);
  EXPECT_EQ(d.g.node(*other)->type, d.g.groups().at("left").type) << "every instance has the new graph";
  EXPECT_EQ(d.g.node(*inst)->params[0].get<double>(), 3.0) << "the instance's own value stays";
  EXPECT_EQ(d.g.source(PortRef{d.mul, 0}), (PortRef{*inst, 0})) << "and its links";
  EXPECT_EQ(d.g.source(PortRef{*inst, 0}), (PortRef{d.c1, 0}));
  // Two moves of one node in a row are one step, inside a group too.
  ASSERT_TRUE(stack.move(d.c2, 10, 10));
  step(stack.move(d.c2, 20, 30));
  EXPECT_EQ(body().node(d.c2)->editor.x, 20);
  const std::size_t outer_nodes = d.g.nodes().size();
  const Result<NodeId> added = stack.add_node("test.Const");
  ASSERT_TRUE(added);
  states.push_back(to_pxg(d.g));
  EXPECT_TRUE(body().node(*added));
  EXPECT_EQ(d.g.nodes().size(), outer_nodes) << "added inside the group, not beside it";
  step(stack.connect(PortRef{*added, 0}, PortRef{d.add1, 1}));
  // The outer graph exposes the instance's left_scale: the inner parameter behind it cannot go.
  const std::string before = to_pxg(d.g);
  EXPECT_EQ(stack.remove_node(d.add1).message(),
            "node " + std::to_string(*inst) + " (left): the edit of group 'left' would remove parameter 'left_scale', which this graph "
            "exposes as 'left_scale'; unexpose it first");
  EXPECT_EQ(to_pxg(d.g), before);
  // A group inside the group, edited through both.
  const Result<NodeId> inner = stack.group({d.c2}, "inner");
  ASSERT_TRUE(inner) << inner.message();
  states.push_back(to_pxg(d.g));
  ASSERT_TRUE(stack.set_scope({*inst, *inner}));
  step(stack.set_param(d.c2, "value", Value::make(9.0)));
  EXPECT_EQ(body().groups().at("inner").type->body->node(d.c2)->params[0].get<double>(), 9.0);

  for (std::size_t i = states.size() - 1; i > 0; --i) {
    ASSERT_TRUE(stack.undo());
    ASSERT_EQ(to_pxg(d.g), states[i - 1]) << "after undoing step " << i;
  }
  EXPECT_EQ(stack.scope(), std::vector<NodeId>{*inst}) << "the nested group node is gone: the scope backs out to it";
  for (std::size_t i = 1; i < states.size(); ++i) {
    ASSERT_TRUE(stack.redo());
    ASSERT_EQ(to_pxg(d.g), states[i]) << "after redoing step " << i;
  }
  // Undoing the grouping from inside: its node goes, and the scope with it.
  while (stack.undo()) {
  }
  EXPECT_TRUE(stack.scope().empty());
  EXPECT_EQ(to_pxg(d.g), exposed);
}

TEST_F(Commands, AGroupReadFromALibraryFileIsNotEditedInsideTheRecipe) {
  auto body = std::make_shared<Graph>();
  test::output(*body, "out", test::constant(*body, 5));
  ASSERT_TRUE(d.g.add_group("facade", body, "lib/facade.pxg"));
  UndoStack stack(d.g);
  const Result<NodeId> inst = stack.add_group_node("facade");
  ASSERT_TRUE(inst);
  EXPECT_EQ(stack.set_scope({*inst}).message(),
            "group 'facade' is read from lib/facade.pxg, which other recipes may use too: open that file to edit it, or Ungroup to edit a copy here");
  EXPECT_TRUE(stack.scope().empty());
  EXPECT_EQ(d.g.set_group_body("facade", body).message(), "group 'facade' is read from lib/facade.pxg: its graph is that file's, edited there");
}

TEST_F(Commands, HistoryIsBounded) {
  UndoStack stack(d.g, 3);
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(stack.set_param(d.c1, "value", Value::make(static_cast<double>(i))));
  int undone = 0;
  while (stack.undo()) ++undone;
  EXPECT_EQ(undone, 3);
  EXPECT_EQ(d.g.node(d.c1)->params[0].get<double>(), 1.0);
}

}  // namespace
}  // namespace procex
