// Parameters that hold expressions: one exposed parameter driving several
// nodes, graph inputs and attributes read by name, refusals that name the
// node, the parameter and the column, the .pxg form, exact caching, the values
// an editor shows, and undo.
#include <gtest/gtest.h>

#include "graph/commands.h"
#include "graph/evaluator.h"
#include "graph/expression_value.h"
#include "graph/pxg.h"
#include "tests/graph/test_graphs.h"
#include "tests/graph/test_nodes.h"

namespace procex {
namespace {

double out(const EvalResult& r, const std::string& name) {
  const Value* v = r.output(name);
  EXPECT_NE(v, nullptr) << name;
  return v ? v->get<double>() : -1;
}

// `width` is node 1's value, exposed; three more nodes follow it:
//   c1 (width) ──────────────► "width"
//   c2 = width * 2 ──────────► "double"
//   c3 = width + levels ─────► "plus_levels"     (levels: an int graph input)
//   add = c1 + c3, scale = width / 10 ──► "scaled"
struct Shared {
  Graph g;
  NodeId c1, c2, c3, add;
};
Shared shared_width() {
  Shared s;
  Graph& g = s.g;
  EXPECT_TRUE(g.add_input(GraphInput{"levels", &value_type<std::int64_t>(), "", Value::make<std::int64_t>(3)}));
  s.c1 = test::constant(g, 4);
  EXPECT_TRUE(g.expose_param(ExposedParam{"width", s.c1, 0}));
  s.c2 = test::constant(g, 0);
  s.c3 = test::constant(g, 0);
  s.add = test::add(g, "test.Add");
  test::link(g, s.c1, 0, s.add, 0);
  test::link(g, s.c3, 0, s.add, 1);
  EXPECT_TRUE(g.set_expression(s.c2, "value", "width * 2"));
  EXPECT_TRUE(g.set_expression(s.c3, "value", "width + levels"));
  EXPECT_TRUE(g.set_expression(s.add, "scale", "width / 10"));
  test::output(g, "width", s.c1);
  test::output(g, "double", s.c2);
  test::output(g, "plus_levels", s.c3);
  test::output(g, "scaled", s.add);
  return s;
}

TEST(ExpressionParam, OneExposedParameterDrivesThreeNodes) {
  Shared s = shared_width();
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "test");
  EvalResult r = ev.evaluate(s.g, {});
  ASSERT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].to_string());
  EXPECT_DOUBLE_EQ(out(r, "double"), 8);
  EXPECT_DOUBLE_EQ(out(r, "plus_levels"), 7);
  EXPECT_DOUBLE_EQ(out(r, "scaled"), (4 + 7) * 0.4);

  ASSERT_TRUE(s.g.set_exposed("width", Value::make(10.0)));  // typed once, followed everywhere
  r = ev.evaluate(s.g, {{"levels", Value::make<std::int64_t>(5)}});
  ASSERT_TRUE(r.ok());
  EXPECT_DOUBLE_EQ(out(r, "width"), 10);
  EXPECT_DOUBLE_EQ(out(r, "double"), 20);
  EXPECT_DOUBLE_EQ(out(r, "plus_levels"), 15);
  EXPECT_DOUBLE_EQ(out(r, "scaled"), 25);
}

TEST(ExpressionParam, ResolvedValuesKeyTheCacheExactly) {
  Shared s = shared_width();
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "test");
  const Hash128 before = ev.hash_outputs(s.g, {}).outputs[1].hash;
  ASSERT_TRUE(ev.evaluate(s.g, {}).ok());
  test::reset_evaluations();
  ASSERT_TRUE(ev.evaluate(s.g, {}).ok());
  EXPECT_EQ(test::evaluations(), 0);  // all hits
  // Another input value reaches c3 (and add) through its expression, not c2.
  ASSERT_TRUE(ev.evaluate(s.g, {{"levels", Value::make<std::int64_t>(9)}}).ok());
  EXPECT_EQ(test::evaluations(), 2);
  // The same value by another expression is another key: the text is hashed too.
  ASSERT_TRUE(s.g.set_expression(s.c2, "value", "2 * width"));
  EXPECT_NE(ev.hash_outputs(s.g, {}).outputs[1].hash, before);
  // A value replaces the expression.
  ASSERT_TRUE(s.g.set_param(s.c2, "value", Value::make(1.0)));
  EXPECT_TRUE(s.g.node(s.c2)->expressions.empty());
}

TEST(ExpressionParam, AttributesComeFromTheEvaluation) {
  Graph g;
  const NodeId c = test::constant(g, 0);
  ASSERT_TRUE(g.set_expression(c, "value", "attr('building:levels', 2) * 3.5"));
  test::output(g, "height", c);
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "test");
  EXPECT_DOUBLE_EQ(out(ev.evaluate(g, {}), "height"), 7);
  EvalOptions options;
  options.attributes = {{"building:levels", "12"}};
  EXPECT_DOUBLE_EQ(out(ev.evaluate(g, {}, {}, options), "height"), 42);
  options.attributes = {{"building:levels", "many"}};
  const EvalResult r = ev.evaluate(g, {}, {}, options);
  EXPECT_DOUBLE_EQ(out(r, "height"), 7);
  ASSERT_EQ(r.diagnostics.size(), 1u);
  EXPECT_EQ(r.diagnostics[0].severity, Severity::kWarning);
  EXPECT_NE(r.diagnostics[0].message.find("parameter 'value': column 1: attribute 'building:levels' is 'many'"), std::string::npos)
      << r.diagnostics[0].message;
}

TEST(ExpressionParam, ValuesTheParameterRefusesFailTheNode) {
  Graph g;
  const NodeId c = test::constant(g, 0);  // value in -1e6..1e6
  ASSERT_TRUE(g.add_input(GraphInput{"x", &value_type<double>(), "", Value::make(1.0)}));
  ASSERT_TRUE(g.set_expression(c, "value", "x * 1e7"));
  test::output(g, "y", c);
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "test");
  EvalResult r = ev.evaluate(g, {});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.diagnostics.back().message.find("parameter 'value': 'x * 1e7' gives a value the parameter refuses"),
            std::string::npos)
      << r.diagnostics.back().message;
  ASSERT_TRUE(g.set_expression(c, "value", "1 / x"));
  r = ev.evaluate(g, {{"x", Value::make(0.0)}});
  EXPECT_NE(r.diagnostics.back().message.find("parameter 'value': column 3: division by zero"), std::string::npos)
      << r.diagnostics.back().message;
}

TEST(ExpressionParam, RefusalsNameNodeParameterAndColumn) {
  Shared s = shared_width();
  EXPECT_EQ(s.g.set_expression(s.c2, "value", "widht * 2").message(),
            "node 2 (test.Const), parameter 'value': column 1: unknown name 'widht' (names are the graph's inputs and "
            "exposed parameters)");
  EXPECT_EQ(s.g.set_expression(s.c2, "value", "width > 2").message(),
            "node 2 (test.Const), parameter 'value': column 1: the expression gives a bool but the parameter takes a float");
  EXPECT_EQ(s.g.set_expression(s.c1, "value", "width + 1").message(),
            "node 1 (test.Const), parameter 'value': the expression reads 'width', which is this parameter itself");
  ASSERT_TRUE(s.g.expose_param(ExposedParam{"twice", s.c2, 0}));
  EXPECT_EQ(s.g.set_expression(s.c1, "value", "twice / 2").message(),
            "node 1 (test.Const), parameter 'value': the expression reads 'width', which is this parameter itself");
  Graph g;
  const NodeId e = test::add(g, "test.Everything");
  EXPECT_EQ(g.set_expression(e, "v2", "1").message(),
            "node 1 (test.Everything), parameter 'v2': a vec2 parameter cannot hold an expression (float, int, bool, "
            "string and enum parameters can)");
  EXPECT_TRUE(g.set_expression(e, "e", "if(1 > 0, 'east', 'west')"));
  EXPECT_TRUE(g.set_expression(e, "i", "round(2.6)"));
}

TEST(ExpressionParam, InputsFedByNodesAreNotKnownBeforeEvaluation) {
  auto body = std::make_shared<Graph>();
  ASSERT_TRUE(body->add_input(GraphInput{"x", &value_type<double>(), "", {}}));
  const NodeId inner = test::constant(*body, 0);
  ASSERT_TRUE(body->set_expression(inner, "value", "x + 1"));
  test::output(*body, "y", inner);
  Graph g;
  ASSERT_TRUE(g.add_input(GraphInput{"x", &value_type<double>(), "", Value::make(4.0)}));
  ASSERT_TRUE(g.add_group("plus_one", body));
  const NodeId by_input = g.add_group_node("plus_one").value();
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 0}, PortRef{by_input, 0}));
  const NodeId by_node = g.add_group_node("plus_one").value();
  test::link(g, test::constant(g, 2), 0, by_node, 0);
  test::output(g, "a", by_input);
  test::output(g, "b", by_node);
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "test");
  const EvalResult r = ev.evaluate(g, {});
  EXPECT_DOUBLE_EQ(out(r, "a"), 5);  // the recipe's own input, through the group's
  EXPECT_EQ(r.output("b"), nullptr);
  ASSERT_FALSE(r.diagnostics.empty());
  EXPECT_NE(r.diagnostics.back().message.find("parameter 'value': column 1: input 'x' is fed by a node's output"),
            std::string::npos)
      << r.diagnostics.back().message;
}

TEST(ExpressionParam, PxgKeepsTheTextAndNamesTheColumnOfMistakes) {
  Shared s = shared_width();
  const std::string text = to_pxg(s.g);
  EXPECT_NE(text.find("\"value\": {\"expr\": \"width * 2\"}"), std::string::npos) << text;
  const Graph back = parse_pxg(text, "shared.pxg");
  EXPECT_EQ(to_pxg(back), text);
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "test");
  EXPECT_EQ(ev.hash_outputs(back, {}).outputs[3].hash, ev.hash_outputs(s.g, {}).outputs[3].hash);

  std::string bad = text;
  bad.replace(bad.find("width * 2"), 9, "width ** 2");
  try {
    parse_pxg(bad, "bad.pxg");
    FAIL() << "accepted";
  } catch (const PxgError& e) {
    EXPECT_EQ(e.where(), "/nodes/1/params/value/expr");
    EXPECT_EQ(e.message(), "node 2 (test.Const), parameter 'value': column 8: unexpected '*'");
  }
  bad = text;
  bad.replace(bad.find("{\"expr\": \"width * 2\"}"), 21, "{\"exp\": \"width\"}");
  try {
    parse_pxg(bad, "bad.pxg");
    FAIL() << "accepted";
  } catch (const PxgError& e) {
    EXPECT_EQ(e.where(), "/nodes/1/params/value");
  }
}

// An editor shows what an expression gave: the node's statistics carry the
// parameters it ran with, for nodes whose parameters are not their own.
TEST(ExpressionParam, StatisticsCarryTheValuesExpressionsGave) {
  Shared s = shared_width();
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "test");
  const EvalResult r = ev.evaluate(s.g, {});
  ASSERT_TRUE(r.ok());
  const NodeStats* c2 = r.stats.find(NodePath{s.c2});
  ASSERT_TRUE(c2);
  ASSERT_EQ(c2->params.size(), 1u);
  EXPECT_DOUBLE_EQ(c2->params[0].get<double>(), 8);
  const NodeStats* c1 = r.stats.find(NodePath{s.c1});
  ASSERT_TRUE(c1);
  EXPECT_TRUE(c1->params.empty()) << "its own values";
  // A cache hit too: the values are known before anything runs.
  const EvalResult again = ev.evaluate(s.g, {});
  ASSERT_TRUE(again.stats.find(NodePath{s.c2}));
  EXPECT_DOUBLE_EQ(again.stats.find(NodePath{s.c2})->params[0].get<double>(), 8);
}

// Each change is one undo step, and undo brings back what the parameter held:
// a value, or another expression. A refusal records nothing.
TEST(ExpressionParam, UndoBringsBackTheValueOrTheExpressionBefore) {
  Shared s = shared_width();
  const std::string start = to_pxg(s.g);
  UndoStack stack(s.g);
  ASSERT_TRUE(stack.set_expression(s.c1, "value", "levels * 2"));  // a value before
  ASSERT_TRUE(stack.set_expression(s.c2, "value", "width * 3"));   // an expression before
  ASSERT_TRUE(stack.set_param(s.c3, "value", Value::make(1.0)));   // a value over an expression
  EXPECT_TRUE(s.g.node(s.c1)->expressions.count(0));
  EXPECT_FALSE(s.g.node(s.c3)->expressions.count(0));
  EXPECT_FALSE(stack.set_expression(s.c2, "value", "width +"));
  EXPECT_EQ(s.g.node(s.c2)->expressions.at(0)->text(), "width * 3");
  int undone = 0;
  while (stack.undo()) ++undone;
  EXPECT_EQ(undone, 3);
  EXPECT_EQ(to_pxg(s.g), start);
}

// The text an editor starts an expression from gives the value back.
TEST(ExpressionParam, LiteralsReadBackAsTheirValues) {
  for (const ExprValue& v : {ExprValue(4.5), ExprValue(-0.1), ExprValue(1e20), ExprValue(1.0 / 3), ExprValue(true), ExprValue(false),
                             ExprValue(std::string("a \"b\" \\ 'c'"))}) {
    const std::string text = expression_literal(v);
    auto e = Expression::parse(text);
    ASSERT_TRUE(e) << text << ": " << e.message();
    EXPECT_EQ((*e)->evaluate({}), v) << text;
  }
}

}  // namespace
}  // namespace procex
