#include "tests/graph/test_graphs.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace procex::test {

namespace {
[[noreturn]] void die(const std::string& what) {
  std::fprintf(stderr, "test graph construction failed: %s\n", what.c_str());
  std::abort();
}
}  // namespace

NodeId add(Graph& g, const std::string& type) {
  Result<NodeId> r = g.add_node(type);
  if (!r) die(r.message());
  return *r;
}

NodeId constant(Graph& g, double v) {
  const NodeId id = add(g, "test.Const");
  if (Status s = g.set_param(id, "value", Value::make(v)); !s) die(s.message());
  return id;
}

void link(Graph& g, NodeId from, std::uint32_t out, NodeId to, std::uint32_t in) {
  if (Status s = g.connect(PortRef{from, out}, PortRef{to, in}); !s) die(s.message());
}

void output(Graph& g, const std::string& name, NodeId from) {
  if (Status s = g.add_output(GraphOutput{name, &value_type<double>(), {}}); !s) die(s.message());
  if (Status s = g.connect(PortRef{from, 0}, PortRef{kGraphOutputs, static_cast<std::uint32_t>(*g.output_index(name))}); !s)
    die(s.message());
}

Diamond diamond() {
  Diamond d;
  d.c1 = constant(d.g, 1);
  d.c2 = constant(d.g, 2);
  d.c3 = constant(d.g, 3);
  d.c4 = constant(d.g, 4);
  d.add1 = add(d.g, "test.Add");
  d.add2 = add(d.g, "test.Add");
  d.mul = add(d.g, "test.Mul");
  link(d.g, d.c1, 0, d.add1, 0);
  link(d.g, d.c2, 0, d.add1, 1);
  link(d.g, d.c3, 0, d.add2, 0);
  link(d.g, d.c4, 0, d.add2, 1);
  link(d.g, d.add1, 0, d.mul, 0);
  link(d.g, d.add2, 0, d.mul, 1);
  output(d.g, "result", d.mul);
  return d;
}

Graph add_tree(std::size_t leaves) {
  Graph g;
  std::vector<NodeId> level;
  for (std::size_t i = 0; i < leaves; ++i) level.push_back(constant(g, static_cast<double>(i)));
  while (level.size() > 1) {
    std::vector<NodeId> next;
    for (std::size_t i = 0; i + 1 < level.size(); i += 2) {
      const NodeId a = add(g, "test.Add");
      link(g, level[i], 0, a, 0);
      link(g, level[i + 1], 0, a, 1);
      next.push_back(a);
    }
    if (level.size() % 2) next.push_back(level.back());
    level = std::move(next);
  }
  output(g, "root", level.front());
  return g;
}

}  // namespace procex::test
