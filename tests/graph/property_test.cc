// Property: random graphs under random edits, cached evaluation equals evaluation from scratch.
#include <gtest/gtest.h>

#include <random>

#include "graph/commands.h"
#include "graph/evaluator.h"
#include "tests/graph/test_graphs.h"

namespace procex {
namespace {

struct RandomEditor {
  std::mt19937 rng;
  Graph& g;
  UndoStack stack;
  int groups = 0;
  int grouped = 0;  // successful group commands
  int ungrouped = 0;

  RandomEditor(unsigned seed, Graph& graph) : rng(seed), g(graph), stack(graph) {}

  std::size_t pick(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }
  NodeId random_node() {
    auto it = g.nodes().begin();
    std::advance(it, static_cast<std::ptrdiff_t>(pick(g.nodes().size())));
    return it->first;
  }

  void add_random_node() {
    static const char* kTypes[] = {"test.Const", "test.Add", "test.Mul", "test.Switch", "test.Fail", "test.Reroute"};
    (void)stack.add_node(kTypes[pick(6)], EditorState{static_cast<double>(pick(500)), 0, {}, false});
  }

  void random_edit() {
    if (g.nodes().size() < 3) return add_random_node();
    switch (pick(10)) {
      case 0: return add_random_node();
      case 1: (void)stack.remove_node(random_node()); return;
      case 2:
      case 3: {  // connect: refusals (types, cycles) are part of the test
        const NodeId a = random_node(), b = random_node();
        const Node* to = g.node(b);
        if (to->decl().inputs().empty() || g.node(a)->decl().outputs().empty()) return;
        (void)stack.connect(PortRef{a, 0}, PortRef{b, static_cast<std::uint32_t>(pick(to->decl().inputs().size()))});
        return;
      }
      case 4: {
        const NodeId b = random_node();
        if (!g.node(b)->decl().inputs().empty()) (void)stack.disconnect(PortRef{b, 0});
        return;
      }
      case 5: {
        const NodeId n = random_node();
        const NodeDecl& d = g.node(n)->decl();
        if (d.params().empty()) return;
        const ParamDecl& p = d.params()[pick(d.params().size())];
        if (p.type == &value_type<double>()) (void)stack.set_param(n, p.name, Value::make(static_cast<double>(pick(7)) - 2));
        else if (p.type == &value_type<bool>()) (void)stack.set_param(n, p.name, Value::make(pick(2) == 0));
        return;
      }
      case 6: (void)stack.move(random_node(), static_cast<double>(pick(100)), static_cast<double>(pick(100))); return;
      case 7: (void)(pick(2) ? stack.undo() : stack.redo()); return;
      case 8: {  // group two nodes (refused when that would make a cycle through the group)
        const NodeId a = random_node(), b = random_node();
        std::string name = "g";
        name += std::to_string(groups++);
        if (stack.group({a, b}, name)) ++grouped;
        return;
      }
      case 9: {
        const NodeId n = random_node();
        if (!g.node(n)->group.empty() && stack.ungroup(n)) ++ungrouped;
        return;
      }
    }
  }
};

// Every node output as a port request, so the whole graph is compared.
std::vector<PortRef> all_ports(const Graph& g) {
  std::vector<PortRef> ports;
  for (const auto& [id, n] : g.nodes())
    for (std::uint32_t o = 0; o < n.decl().outputs().size(); ++o) ports.push_back(PortRef{id, o});
  return ports;
}

TEST(Property, CachedEvaluationEqualsEvaluationFromScratch) {
  constexpr int kGraphs = 24, kEdits = 60;
  int grouped = 0, ungrouped = 0;
  for (unsigned seed = 1; seed <= kGraphs; ++seed) {
    Graph g;
    RandomEditor ed(seed, g);
    for (int i = 0; i < 8; ++i) ed.add_random_node();
    ResultCache cache(1 << 20);  // small enough that eviction happens too
    Evaluator cached(cache, "property");
    for (int step = 0; step < kEdits; ++step) {
      ed.random_edit();
      const auto ports = all_ports(g);
      EvalResult a = cached.evaluate_ports(g, {}, ports);
      ResultCache fresh_cache(1 << 20);
      Evaluator fresh(fresh_cache, "property");
      EvalOptions serial;
      serial.parallel = step % 2 == 0;
      EvalResult b = fresh.evaluate_ports(g, {}, ports, serial);
      ASSERT_EQ(a.outputs.size(), b.outputs.size());
      for (std::size_t i = 0; i < a.outputs.size(); ++i) {
        const OutputResult &x = a.outputs[i], &y = b.outputs[i];
        ASSERT_EQ(x.hash, y.hash) << "seed " << seed << " step " << step << " " << x.name;
        ASSERT_EQ(x.value.empty(), y.value.empty()) << "seed " << seed << " step " << step << " " << x.name;
        if (!x.value.empty()) {
          ASSERT_EQ(x.value.content_hash(), y.value.content_hash()) << x.name;
        }
      }
      ASSERT_EQ(a.diagnostics.size(), b.diagnostics.size()) << "seed " << seed << " step " << step;
      for (std::size_t i = 0; i < a.diagnostics.size(); ++i)
        ASSERT_EQ(a.diagnostics[i].to_string(), b.diagnostics[i].to_string());
    }
    grouped += ed.grouped;
    ungrouped += ed.ungrouped;
  }
  EXPECT_GT(grouped, kGraphs / 2);  // groups are part of what was compared
  EXPECT_GT(ungrouped, 0);
}

}  // namespace
}  // namespace procex
