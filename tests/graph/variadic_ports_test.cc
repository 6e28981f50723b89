// Variadic ports: a parameter that sets a port count (ParamBuilder::sets_port_count)
// gives each node the declaration for its own count: links, evaluation, hashes,
// undo and files follow it; removing a connected port is refused with a reason.
#include <gtest/gtest.h>

#include "graph/commands.h"
#include "graph/evaluator.h"
#include "graph/pxg.h"
#include "tests/graph/test_graphs.h"
#include "tests/graph/test_nodes.h"

namespace procex {
namespace {

using test::add;
using test::constant;

Value terms(std::int64_t n) { return Value::make<std::int64_t>(n); }

//   c1  c2  c3  c4
//     \  \  /  /
//       sum (4 terms) -> "sum"
struct Sum4 {
  Graph g;
  NodeId sum = 0;
};
Sum4 sum_of_four() {
  Sum4 s;
  s.sum = add(s.g, "test.Sum");
  EXPECT_TRUE(s.g.set_param(s.sum, "terms", terms(4)));
  for (std::uint32_t i = 0; i < 4; ++i) test::link(s.g, constant(s.g, 1.0 + i), 0, s.sum, i);
  test::output(s.g, "sum", s.sum);
  return s;
}

TEST(VariadicPorts, TheCountSetsTheDeclaration) {
  Graph g;
  const NodeId sum = add(g, "test.Sum");
  ASSERT_EQ(g.node(sum)->decl().inputs().size(), 2u);
  const auto* base = &g.node(sum)->decl();
  ASSERT_TRUE(g.set_param(sum, "terms", terms(5)));
  const NodeDecl& five = g.node(sum)->decl();
  ASSERT_EQ(five.inputs().size(), 5u);
  EXPECT_EQ(five.inputs()[4].name, "term_5");
  EXPECT_EQ(five.params().size(), 2u);
  ASSERT_TRUE(g.set_param(sum, "terms", terms(2)));
  EXPECT_EQ(&g.node(sum)->decl(), base);  // back to the registered type
  Graph other;
  const NodeId again = add(other, "test.Sum");
  ASSERT_TRUE(other.set_param(again, "terms", terms(5)));
  EXPECT_EQ(&other.node(again)->decl(), &five);  // variants are made once and shared
  EXPECT_EQ(g.set_param(sum, "terms", terms(9)).message(), "parameter 'terms' = 9 is outside its range [1, 8]");
}

TEST(VariadicPorts, EvaluationAndHashesFollowTheCount) {
  Sum4 s = sum_of_four();
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "variadic");
  const EvalResult r = ev.evaluate(s.g, {});
  ASSERT_TRUE(r.ok()) << r.diagnostics.at(0).to_string();
  EXPECT_EQ(r.output("sum")->get<double>(), 1 + 2 + 3 + 4);
  Graph more = s.g;
  ASSERT_TRUE(more.set_param(s.sum, "terms", terms(6)));  // two more, unconnected
  EXPECT_EQ(ev.evaluate(more, {}).output("sum")->get<double>(), 10.0);
  EXPECT_NE(ev.hash_outputs(more, {}).outputs[0].hash, r.outputs[0].hash);
}

TEST(VariadicPorts, RemovingAConnectedPortIsRefused) {
  Sum4 s = sum_of_four();
  EXPECT_EQ(s.g.set_param(s.sum, "terms", terms(3)).message(),
            "node 1 (test.Sum): 'terms' = 3 would remove input 'term_4', which is connected; disconnect it first");
  EXPECT_EQ(s.g.node(s.sum)->decl().inputs().size(), 4u);
  EXPECT_EQ(s.g.node(s.sum)->params[0].get<std::int64_t>(), 4);  // nothing changed
  ASSERT_TRUE(s.g.disconnect(PortRef{s.sum, 3}));
  EXPECT_TRUE(s.g.set_param(s.sum, "terms", terms(3)));
  EXPECT_FALSE(s.g.connect(PortRef{2, 0}, PortRef{s.sum, 3}));  // term_4 is gone
}

TEST(VariadicPorts, UndoBringsThePortsBack) {
  Sum4 s = sum_of_four();
  UndoStack stack(s.g);
  ASSERT_TRUE(stack.disconnect(PortRef{s.sum, 3}));
  ASSERT_TRUE(stack.set_param(s.sum, "terms", terms(3)));
  ASSERT_EQ(s.g.node(s.sum)->decl().inputs().size(), 3u);
  ASSERT_TRUE(stack.undo());
  ASSERT_TRUE(stack.undo());
  EXPECT_EQ(s.g.node(s.sum)->decl().inputs().size(), 4u);
  EXPECT_TRUE(s.g.source(PortRef{s.sum, 3}).has_value());
  ASSERT_TRUE(stack.redo());
  ASSERT_TRUE(stack.redo());
  EXPECT_EQ(s.g.node(s.sum)->decl().inputs().size(), 3u);
}

TEST(VariadicPorts, FilesKeepTheCountAndItsLinks) {
  Sum4 s = sum_of_four();
  const std::string text = to_pxg(s.g);
  EXPECT_NE(text.find("\"terms\": 4"), std::string::npos) << text;
  const Graph back = parse_pxg(text, "sum4.pxg");
  EXPECT_EQ(to_pxg(back), text);
  EXPECT_EQ(back.node(s.sum)->decl().inputs().size(), 4u);
  EXPECT_TRUE(back.source(PortRef{s.sum, 3}).has_value());
}

// Version 1 had three fixed inputs; its upgrade sets the count before links are read.
TEST(VariadicPorts, OlderVersionsUpgradeToTheirFixedCount) {
  const std::string v1 = R"({"format": "procex-graph", "version": 2,
    "nodes": [{"id": 1, "type": "test.Const", "version": 1, "params": {"value": 5.0}},
              {"id": 2, "type": "test.Sum", "version": 1, "params": {"offset": 0.0}}],
    "links": [{"from": "1.out", "to": "2.term_3"}], "inputs": [], "outputs": [], "exposed": [], "groups": []})";
  const Graph g = parse_pxg(v1, "v1_sum.pxg");
  EXPECT_EQ(g.node(2)->params[0].get<std::int64_t>(), 3);
  EXPECT_EQ(g.source(PortRef{2, 2}), (PortRef{1, 0}));
  // A count beyond the range is refused where it stands.
  const std::string too_many = R"({"format": "procex-graph", "version": 2,
    "nodes": [{"id": 2, "type": "test.Sum", "version": 2, "params": {"offset": 0.0, "terms": 1000000}}],
    "links": [], "inputs": [], "outputs": [], "exposed": [], "groups": []})";
  try {
    parse_pxg(too_many, "huge.pxg");
    FAIL() << "a million ports were accepted";
  } catch (const PxgError& e) {
    EXPECT_NE(std::string(e.what()).find("/nodes/0/params/terms"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("outside its range"), std::string::npos) << e.what();
  }
}

// Grouping keeps a node's own ports (the group's body holds the same node),
// and so does ungrouping.
TEST(VariadicPorts, GroupingKeepsThePorts) {
  Sum4 s = sum_of_four();
  ResultCache cache(1 << 20);
  Evaluator ev(cache, "variadic");
  const Hash128 before = ev.hash_outputs(s.g, {}).outputs[0].hash;
  UndoStack stack(s.g);
  const Result<NodeId> group = stack.group({s.sum, 5}, "sum_group");  // the sum and its fourth term
  ASSERT_TRUE(group) << group.message();
  EXPECT_EQ(ev.evaluate(s.g, {}).output("sum")->get<double>(), 10.0);
  EXPECT_EQ(ev.hash_outputs(s.g, {}).outputs[0].hash, before);
  const std::string text = to_pxg(s.g);
  EXPECT_EQ(to_pxg(parse_pxg(text, "grouped.pxg")), text);
  ASSERT_TRUE(stack.ungroup(*group));
  EXPECT_EQ(ev.evaluate(s.g, {}).output("sum")->get<double>(), 10.0);
  std::size_t sums = 0;
  for (const auto& [id, node] : s.g.nodes()) {
    if (node.type->name() != "test.Sum") continue;
    ++sums;
    EXPECT_EQ(node.decl().inputs().size(), 4u);
  }
  EXPECT_EQ(sums, 1u);
}

TEST(VariadicPorts, ACountCannotBeExposed) {
  Graph g;
  const NodeId sum = add(g, "test.Sum");
  EXPECT_EQ(g.expose_param({"n", sum, 0}).message(),
            "exposed parameter 'n': 'terms' of node 1 sets its number of ports, which a group's users cannot change");
  EXPECT_TRUE(g.expose_param({"offset", sum, 1}));
}

TEST(VariadicPorts, DeclarationsAreChecked) {
  NodeDecl unbounded("Unbounded", 1);
  unbounded.param<std::int64_t>("n").default_value<std::int64_t>(2).sets_port_count();
  EXPECT_EQ(unbounded.validate().message(), "node type 'Unbounded': parameter 'n' sets a port count: make it a "
                                            "list<string>, or an int with a range within 0..64");
  NodeDecl listed("Listed", 1);
  listed.param<std::vector<std::string>>("cases").default_value(std::vector<std::string>{"a", "b", "c"}).sets_port_count();
  EXPECT_TRUE(listed.validate());
  EXPECT_EQ(listed.count_of("cases"), 3u);
  EXPECT_EQ(listed.params()[0].check(Value::make(std::vector<std::string>(65))).message(),
            "parameter 'cases' asks for 65 ports; at most 64");
}

}  // namespace
}  // namespace procex
