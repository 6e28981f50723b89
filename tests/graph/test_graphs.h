// test_graphs.h -- small graphs of the test nodes, shared by the graph/ tests and the benchmark.
#pragma once

#include <cstdint>
#include <string>

#include "graph/graph.h"

namespace procex::test {

// Adds a node or fails the test (and aborts when used outside a test).
NodeId add(Graph& g, const std::string& type);
NodeId constant(Graph& g, double v);
void link(Graph& g, NodeId from, std::uint32_t out, NodeId to, std::uint32_t in);
// Declares a float graph output `name` fed by node `from` output 0.
void output(Graph& g, const std::string& name, NodeId from);

//   c1   c2      c3   c4
//     \ /          \ /
//     add1         add2
//         \       /
//           mul  -> "result"
struct Diamond {
  Graph g;
  NodeId c1, c2, c3, c4, add1, add2, mul;
};
Diamond diamond();

// A balanced binary tree of test.Add with `leaves` constants: 2*leaves - 1 nodes, output "root".
Graph add_tree(std::size_t leaves);

}  // namespace procex::test
