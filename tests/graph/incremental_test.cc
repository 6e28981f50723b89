// Only what changed recomputes: after each kind of edit, count node evaluations.
#include <gtest/gtest.h>

#include "graph/commands.h"
#include "graph/evaluator.h"
#include "tests/graph/test_graphs.h"
#include "tests/graph/test_nodes.h"

namespace procex {
namespace {

class Incremental : public ::testing::Test {
 protected:
  void SetUp() override {
    d = test::diamond();
    ASSERT_TRUE(ev.evaluate(d.g, {}).ok());
    test::reset_evaluations();
  }
  int reevaluate() {
    test::reset_evaluations();
    last = ev.evaluate(d.g, {});
    EXPECT_TRUE(last.ok());
    return test::evaluations();
  }
  test::Diamond d;
  ResultCache cache{64 << 20};
  Evaluator ev{cache, "incremental"};
  EvalResult last;
};

TEST_F(Incremental, NothingChangedNothingRuns) { EXPECT_EQ(reevaluate(), 0); }

TEST_F(Incremental, ParameterEditRerunsTheNodeAndItsDownstreamOnly) {
  ASSERT_TRUE(d.g.set_param(d.c1, "value", Value::make(10.0)));
  EXPECT_EQ(reevaluate(), 3);  // c1, add1, mul
  EXPECT_EQ(test::evaluations_of("test.Const"), 1);
  EXPECT_EQ(test::evaluations_of("test.Add"), 1);
  EXPECT_EQ(test::evaluations_of("test.Mul"), 1);
  EXPECT_EQ(last.output("result")->get<double>(), 12.0 * 7.0);
}

TEST_F(Incremental, MovingANodeRerunsNothing) {
  UndoStack stack(d.g);
  ASSERT_TRUE(stack.move(d.add2, 300, 120));
  ASSERT_TRUE(stack.set_editor_state(d.mul, EditorState{1, 2, "final product", true}));
  EXPECT_EQ(reevaluate(), 0);
}

TEST_F(Incremental, UndoBringsTheCachedResultBack) {
  UndoStack stack(d.g);
  ASSERT_TRUE(stack.set_param(d.add2, "scale", Value::make(2.0)));
  EXPECT_EQ(reevaluate(), 2);  // add2, mul
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(reevaluate(), 0);
  EXPECT_EQ(last.output("result")->get<double>(), 21.0);
  ASSERT_TRUE(stack.redo());
  EXPECT_EQ(reevaluate(), 0);
  EXPECT_EQ(last.output("result")->get<double>(), 3.0 * 14.0);
}

TEST_F(Incremental, RelinkingRerunsOnlyTheNewDownstream) {
  UndoStack stack(d.g);
  ASSERT_TRUE(stack.connect(PortRef{d.c1, 0}, PortRef{d.add2, 1}));  // replaces c4 -> add2
  EXPECT_EQ(reevaluate(), 2);                                        // add2, mul
  EXPECT_EQ(last.output("result")->get<double>(), 3.0 * 4.0);
  ASSERT_TRUE(stack.disconnect(PortRef{d.add2, 1}));  // b is optional
  EXPECT_EQ(reevaluate(), 2);
  ASSERT_TRUE(stack.undo());
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(reevaluate(), 0);
}

TEST_F(Incremental, AddingAndRemovingUnrelatedNodesRerunsNothing) {
  UndoStack stack(d.g);
  auto extra = stack.add_node("test.Const");
  ASSERT_TRUE(extra);
  EXPECT_EQ(reevaluate(), 0);
  ASSERT_TRUE(stack.remove_node(*extra));
  EXPECT_EQ(reevaluate(), 0);
}

TEST_F(Incremental, RemovingAnInputRerunsItsConsumers) {
  UndoStack stack(d.g);
  ASSERT_TRUE(stack.remove_node(d.c2));  // add1.b is optional: add1 and mul rerun
  EXPECT_EQ(reevaluate(), 2);
  EXPECT_EQ(last.output("result")->get<double>(), 1.0 * 7.0);
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(reevaluate(), 0);
  EXPECT_EQ(last.output("result")->get<double>(), 21.0);
}

TEST_F(Incremental, GroupingKeepsTheResultsCached) {
  UndoStack stack(d.g);
  auto inst = stack.group({d.c1, d.c2, d.add1}, "left");
  ASSERT_TRUE(inst) << inst.message();
  EXPECT_EQ(reevaluate(), 0);  // same nodes, same parameters, same hashes inside the group
  EXPECT_EQ(last.output("result")->get<double>(), 21.0);
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(reevaluate(), 0);
  ASSERT_TRUE(stack.redo());
  ASSERT_TRUE(stack.ungroup(*inst));
  EXPECT_EQ(reevaluate(), 0);  // ungrouped nodes hash as they did inside the group
}

TEST_F(Incremental, ChangingTheEngineSaltRecomputesEverything) {
  Evaluator newer(cache, "incremental-v2");
  test::reset_evaluations();
  EXPECT_TRUE(newer.evaluate(d.g, {}).ok());
  EXPECT_EQ(test::evaluations(), 7);
}

}  // namespace
}  // namespace procex
