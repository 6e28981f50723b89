#include <gtest/gtest.h>

#include "graph/graph.h"
#include "tests/graph/test_graphs.h"

namespace procex {
namespace {

using test::add;
using test::constant;

TEST(Graph, NodesGetStableIncreasingIdsAndDefaults) {
  Graph g;
  const NodeId a = constant(g, 5);
  const NodeId b = add(g, "test.Add");
  EXPECT_EQ(a, 1u);
  EXPECT_EQ(b, 2u);
  EXPECT_EQ(g.node(b)->params[0].get<double>(), 1.0);
  ASSERT_TRUE(g.remove_node(a));
  EXPECT_EQ(add(g, "test.Const"), 3u);  // ids are never reused
  EXPECT_EQ(g.add_node("test.Const", 2).message(), "node id 2 is already taken");
  EXPECT_EQ(g.add_node("test.Ad").message(), "unknown node type 'test.Ad'; did you mean 'test.Add'?");
}

TEST(Graph, LinksAreTypeCheckedWithAReason) {
  Graph g;
  const NodeId e = add(g, "test.Everything");
  const NodeId a = add(g, "test.Add");
  EXPECT_EQ(g.connect(PortRef{e, 0}, PortRef{a, 0}).message(),
            "cannot link 1.summary (string) to 2.a (float): the types differ");
  EXPECT_EQ(g.connect(PortRef{e, 5}, PortRef{a, 0}).message(), "there is no output 1.#5 to link from");
  EXPECT_EQ(g.connect(PortRef{9, 0}, PortRef{a, 0}).message(), "there is no output 9.#0 to link from");
  const NodeId c = constant(g, 1);
  ASSERT_TRUE(g.connect(PortRef{c, 0}, PortRef{a, 0}));
  EXPECT_EQ(g.connect(PortRef{c, 0}, PortRef{a, 0}).message(), "input 2.a is already fed by 3.out; disconnect it first");
  // Any-typed ports take everything.
  const NodeId r = add(g, "test.Reroute");
  EXPECT_TRUE(g.connect(PortRef{e, 0}, PortRef{r, 0}));
}

TEST(Graph, CyclesAreRefused) {
  Graph g;
  const NodeId a = add(g, "test.Add");
  const NodeId b = add(g, "test.Add");
  const NodeId c = add(g, "test.Add");
  ASSERT_TRUE(g.connect(PortRef{a, 0}, PortRef{b, 0}));
  ASSERT_TRUE(g.connect(PortRef{b, 0}, PortRef{c, 0}));
  EXPECT_EQ(g.connect(PortRef{c, 0}, PortRef{a, 0}).message(),
            "linking 3.sum to 1.a would make a cycle: node 3 already depends on node 1");
  EXPECT_FALSE(g.connect(PortRef{a, 0}, PortRef{a, 1}));
  EXPECT_TRUE(g.connect(PortRef{a, 0}, PortRef{c, 1}));
}

TEST(Graph, RemovingANodeRemovesItsLinksAndExposure) {
  test::Diamond d = test::diamond();
  ASSERT_TRUE(d.g.expose_param(ExposedParam{"scale", d.add1, 0}));
  const std::size_t before = d.g.links().size();
  ASSERT_TRUE(d.g.remove_node(d.add1));
  EXPECT_EQ(d.g.links().size(), before - 3);
  EXPECT_TRUE(d.g.exposed_params().empty());
  EXPECT_FALSE(d.g.source(PortRef{d.mul, 0}));
}

TEST(Graph, ParametersAreCheckedOnSet) {
  Graph g;
  const NodeId a = add(g, "test.Add");
  EXPECT_EQ(g.set_param(a, "scale", Value::make(1000.0)).message(), "parameter 'scale' = 1000 is outside its range [-100, 100]");
  EXPECT_EQ(g.set_param(a, "scael", Value::make(1.0)).message(), "node 1 (test.Add) has no parameter 'scael'");
  EXPECT_TRUE(g.set_param(a, "scale", Value::make(-3.0)));
}

TEST(Graph, InterfacePortsAndRenumbering) {
  Graph g;
  ASSERT_TRUE(g.add_input(GraphInput{"a", &value_type<double>(), "", {}}));
  ASSERT_TRUE(g.add_input(GraphInput{"b", &value_type<double>(), "", {}}));
  EXPECT_EQ(g.add_input(GraphInput{"b", &value_type<double>(), "", {}}).message(), "there is already a graph input named 'b'");
  EXPECT_EQ(g.add_input(GraphInput{"c", &value_type<double>(), "", Value::make(true)}).message(),
            "graph input 'c' is float but its default is bool");
  const NodeId n = add(g, "test.Add");
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 1}, PortRef{n, 0}));
  ASSERT_TRUE(g.remove_input("a"));
  EXPECT_EQ(g.source(PortRef{n, 0}), (PortRef{kGraphInputs, 0}));  // "b" moved to index 0
  EXPECT_EQ(g.port_name(PortRef{kGraphInputs, 0}, true), "@b");
}

TEST(Graph, ValidateListsUnconnectedInputsAndOutputs) {
  Graph g;
  add(g, "test.Add");
  ASSERT_TRUE(g.add_output(GraphOutput{"x", &value_type<double>(), ""}));
  auto problems = g.validate();
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].to_string(), "error: node 1 (test.Add): input 'a' is not connected");
  EXPECT_EQ(problems[1].to_string(), "error: graph output 'x' is not connected");
}

TEST(Graph, GroupTypesDeriveTheirDeclaration) {
  auto body = std::make_shared<Graph>();
  ASSERT_TRUE(body->add_input(GraphInput{"x", &value_type<double>(), "the x", {}}));
  const NodeId a = add(*body, "test.Add");
  ASSERT_TRUE(body->connect(PortRef{kGraphInputs, 0}, PortRef{a, 0}));
  test::output(*body, "y", a);
  ASSERT_TRUE(body->set_param(a, "scale", Value::make(3.0)));
  ASSERT_TRUE(body->expose_param(ExposedParam{"factor", a, 0}));
  Graph g;
  ASSERT_TRUE(g.add_group("triple", body));
  const GroupDef& def = g.groups().at("triple");
  const NodeDecl& d = def.type->decl;
  ASSERT_EQ(d.inputs().size(), 1u);
  EXPECT_EQ(d.inputs()[0].doc, "the x");
  ASSERT_EQ(d.params().size(), 1u);
  EXPECT_EQ(d.params()[0].name, "factor");
  EXPECT_EQ(d.params()[0].default_value.get<double>(), 3.0);
  EXPECT_EQ(*d.params()[0].max, 100.0);
  const NodeId inst = g.add_group_node("triple").value();
  ASSERT_TRUE(g.expose_param(ExposedParam{"outer_factor", inst, 0}));
  EXPECT_TRUE(g.set_exposed("outer_factor", Value::make(4.0)));
  EXPECT_EQ(g.node(inst)->params[0].get<double>(), 4.0);
  EXPECT_EQ(g.set_exposed("outer_factor", Value::make(400.0)).message(),
            "parameter 'factor' = 400 is outside its range [-100, 100]");
  EXPECT_EQ(g.set_exposed("nope", Value::make(1.0)).message(), "no exposed parameter 'nope'");
  EXPECT_EQ(g.node(inst)->group, "triple");
  EXPECT_EQ(g.remove_group("triple").message(), "group 'triple' is still used by node 1");
  EXPECT_EQ(g.add_group_node("nope").message(), "no group named 'nope' in this recipe");
}

}  // namespace
}  // namespace procex
