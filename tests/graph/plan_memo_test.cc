// A batch's plans reused across its buildings (EvalOptions::plans, PlanMemo):
// every evaluation gives what it gives without the memo, while a plan is
// reused whenever planning would read the same values. Each test changes one
// thing planning reads, the way a batch's features do (an exposed value set on
// a copy of the recipe, an attribute, an input an expression reads), and
// would get the other branch's plan, or its keys, if the memo missed it.
#include <gtest/gtest.h>

#include "graph/evaluator.h"
#include "tests/graph/test_graphs.h"
#include "tests/graph/test_nodes.h"

namespace procex {
namespace {

using test::add;
using test::link;

class PlanMemoTest : public ::testing::Test {
 protected:
  //   x -> add (scale 1) -- first
  //                            pick ("kind") -> "out"
  //   x -> add (scale 10) -- second
  void SetUp() override {
    test::reset_evaluations();
    options_.pin_files_for_a_batch();
    ASSERT_TRUE(g_.add_input(GraphInput{"x", &value_type<double>(), "", {}}));
    ASSERT_TRUE(g_.add_input(GraphInput{"choice", &value_type<std::int64_t>(), "", Value::make<std::int64_t>(0)}));
    const NodeId once = add(g_, "test.Add");
    const NodeId ten = add(g_, "test.Add");
    pick_ = add(g_, "test.Pick");
    ASSERT_TRUE(g_.set_param(ten, "scale", Value::make(10.0)));
    ASSERT_TRUE(g_.connect(PortRef{kGraphInputs, 0}, PortRef{once, 0}));
    ASSERT_TRUE(g_.connect(PortRef{kGraphInputs, 0}, PortRef{ten, 0}));
    link(g_, once, 0, pick_, 0);
    link(g_, ten, 0, pick_, 1);
    ASSERT_TRUE(g_.expose_param(ExposedParam{"kind", pick_, 0}));
    ASSERT_TRUE(g_.add_output(GraphOutput{"out", &value_type<double>(), ""}));
    ASSERT_TRUE(g_.connect(PortRef{pick_, 0}, PortRef{kGraphOutputs, 0}));
  }

  // "out" for x, as a batch's building gets it: the graph a copy of the recipe.
  double out(const Graph& g, double x, Bindings bindings = {}) {
    bindings["x"] = Value::make(x);
    const EvalResult r = ev_.evaluate(g, bindings, {"out"}, options_);
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].to_string());
    return r.ok() ? r.output("out")->get<double>() : -1;
  }
  Graph with_kind(std::int64_t kind) const {
    Graph copy = g_;
    EXPECT_TRUE(copy.set_exposed("kind", Value::make<std::int64_t>(kind)));
    return copy;
  }

  ResultCache cache_{64 << 20};
  Evaluator ev_{cache_, "test-engine-1"};
  EvalOptions options_;
  Graph g_;
  NodeId pick_ = 0;
};

// city.pxg's building type: the property `building` sets the Switch's exposed value.
TEST_F(PlanMemoTest, AnExposedValueSetOnACopyOfTheRecipeGetsItsOwnPlan) {
  EXPECT_EQ(out(with_kind(0), 2), 2.0);
  EXPECT_EQ(out(with_kind(1), 2), 20.0);
  EXPECT_EQ(out(with_kind(0), 3), 3.0);  // the first plan, its keys finished with x = 3
  EXPECT_EQ(out(with_kind(1), 5), 50.0);
  EXPECT_EQ(options_.plans->size(), 2u);
  EXPECT_EQ(test::evaluations_of("test.Add"), 4);  // no building took another's result
}

// city.pxg's levels and floor heights: attr() in parameters. Only the
// attributes planning read key a plan: a feature's other properties do not.
TEST_F(PlanMemoTest, TheAttributesExpressionsReadKeyAPlan) {
  ASSERT_TRUE(g_.set_expression(pick_, "which", "attr('kind', 0)"));
  options_.attributes = {{"kind", "1"}, {"name", "a"}};
  EXPECT_EQ(out(g_, 2), 20.0);
  options_.attributes = {{"kind", "1"}, {"name", "b"}};
  EXPECT_EQ(out(g_, 3), 30.0);
  EXPECT_EQ(options_.plans->size(), 1u);
  options_.attributes = {{"name", "c"}};
  EXPECT_EQ(out(g_, 3), 3.0);
  options_.attributes = {{"kind", "0"}};
  EXPECT_EQ(out(g_, 4), 4.0);
  EXPECT_EQ(options_.plans->size(), 3u);  // "kind" absent and "kind" = "0" are two readings
}

// An expression that reads a bound input: that input's value keys the plan;
// the others' values only finish its keys.
TEST_F(PlanMemoTest, TheInputsExpressionsReadKeyAPlan) {
  ASSERT_TRUE(g_.set_expression(pick_, "which", "choice"));
  EXPECT_EQ(out(g_, 2, {{"choice", Value::make<std::int64_t>(1)}}), 20.0);
  EXPECT_EQ(out(g_, 2, {{"choice", Value::make<std::int64_t>(0)}}), 2.0);
  EXPECT_EQ(out(g_, 7, {{"choice", Value::make<std::int64_t>(1)}}), 70.0);
  EXPECT_EQ(out(g_, 7), 7.0);  // unbound: its default, 0
  EXPECT_EQ(options_.plans->size(), 2u);
}

// The same through a group: its body's expression reads a group input fed by
// a graph input, as city.pxg's groups read the building's inputs.
TEST_F(PlanMemoTest, AGroupInputAnExpressionReadsKeysThePlan) {
  auto body = std::make_shared<Graph>();
  ASSERT_TRUE(body->add_input(GraphInput{"x", &value_type<double>(), "", {}}));
  ASSERT_TRUE(body->add_input(GraphInput{"n", &value_type<std::int64_t>(), "", Value::make<std::int64_t>(1)}));
  const NodeId scaled = add(*body, "test.Add");
  ASSERT_TRUE(body->connect(PortRef{kGraphInputs, 0}, PortRef{scaled, 0}));
  ASSERT_TRUE(body->set_expression(scaled, "scale", "n"));
  test::output(*body, "y", scaled);
  Graph g;
  ASSERT_TRUE(g.add_group("scaler", body));
  ASSERT_TRUE(g.add_input(GraphInput{"x", &value_type<double>(), "", {}}));
  ASSERT_TRUE(g.add_input(GraphInput{"n", &value_type<std::int64_t>(), "", {}}));
  const NodeId group = g.add_group_node("scaler").value();
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 0}, PortRef{group, 0}));
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 1}, PortRef{group, 1}));
  ASSERT_TRUE(g.add_output(GraphOutput{"out", &value_type<double>(), ""}));
  ASSERT_TRUE(g.connect(PortRef{group, 0}, PortRef{kGraphOutputs, 0}));
  EXPECT_EQ(out(g, 3, {{"n", Value::make<std::int64_t>(2)}}), 6.0);
  EXPECT_EQ(out(g, 3, {{"n", Value::make<std::int64_t>(5)}}), 15.0);
  EXPECT_EQ(out(g, 4, {{"n", Value::make<std::int64_t>(2)}}), 8.0);
  EXPECT_EQ(options_.plans->size(), 2u);
}

// A plan reused keys its nodes as a fresh one does: the cache and the
// statistics see the same keys with and without the memo.
TEST_F(PlanMemoTest, AReusedPlanGivesTheKeysOfAFreshOne) {
  EvalOptions fresh;
  for (const double x : {2.0, 3.0, 2.0}) {
    const Bindings b{{"x", Value::make(x)}};
    const EvalResult memo = ev_.evaluate(with_kind(1), b, {"out"}, options_);
    const EvalResult plain = ev_.evaluate(with_kind(1), b, {"out"}, fresh);
    EXPECT_EQ(memo.outputs[0].hash, plain.outputs[0].hash);
    ASSERT_EQ(memo.stats.nodes.size(), plain.stats.nodes.size());
    for (std::size_t i = 0; i < memo.stats.nodes.size(); ++i) {
      EXPECT_EQ(memo.stats.nodes[i].path, plain.stats.nodes[i].path);
      EXPECT_EQ(memo.stats.nodes[i].key, plain.stats.nodes[i].key);
    }
  }
  EXPECT_EQ(options_.plans->size(), 1u);
}

TEST(GraphTest, CopiesEvaluateAlikeUntilAValueDiffers) {
  Graph g;
  const NodeId c = test::constant(g, 2);
  test::output(g, "out", c);
  ASSERT_TRUE(g.expose_param(ExposedParam{"value", c, 0}));
  Graph copy = g;
  EXPECT_TRUE(copy.evaluates_like(g));
  ASSERT_TRUE(copy.set_exposed("value", Value::make(2.0)));  // another Value, the same content
  EXPECT_TRUE(copy.evaluates_like(g));
  ASSERT_TRUE(copy.set_exposed("value", Value::make(3.0)));
  EXPECT_FALSE(copy.evaluates_like(g));
  Graph moved = g;
  ASSERT_TRUE(moved.set_editor_state(c, EditorState{5, 5, "note", true}));
  EXPECT_TRUE(moved.evaluates_like(g));
  Graph linked = g;
  ASSERT_TRUE(linked.disconnect(PortRef{kGraphOutputs, 0}));
  EXPECT_FALSE(linked.evaluates_like(g));
}

}  // namespace
}  // namespace procex
