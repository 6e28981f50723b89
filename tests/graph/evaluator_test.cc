#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "graph/evaluator.h"
#include "tests/graph/test_graphs.h"
#include "tests/graph/test_nodes.h"
#include "tests/support/scratch_dir.h"

namespace procex {
namespace {

using test::add;
using test::constant;
using test::link;

class EvaluatorTest : public ::testing::Test {
 protected:
  void SetUp() override { test::reset_evaluations(); }
  ResultCache cache{64 << 20};
  Evaluator ev{cache, "test-engine-1"};
};

TEST_F(EvaluatorTest, EvaluatesADiamond) {
  test::Diamond d = test::diamond();
  EvalResult r = ev.evaluate(d.g, {});
  ASSERT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].to_string());
  EXPECT_EQ(r.output("result")->get<double>(), (1 + 2) * (3 + 4));
  EXPECT_EQ(r.stats.computed(), 7u);
  EXPECT_EQ(test::evaluations(), 7);
}

TEST_F(EvaluatorTest, PullsOnlyWhatTheRequestNeeds) {
  test::Diamond d = test::diamond();
  test::output(d.g, "left", d.add1);
  EvalResult r = ev.evaluate(d.g, {}, {"left"});
  EXPECT_EQ(r.output("left")->get<double>(), 3.0);
  EXPECT_EQ(test::evaluations(), 3);  // c1, c2, add1
  // A cached downstream result spares its whole upstream.
  ev.evaluate(d.g, {}, {"result"});
  test::reset_evaluations();
  EvalResult again = ev.evaluate(d.g, {}, {"result"});
  EXPECT_EQ(test::evaluations(), 0);
  ASSERT_EQ(again.stats.nodes.size(), 1u);
  EXPECT_EQ(again.stats.nodes[0].outcome, NodeOutcome::kCacheHit);
}

TEST_F(EvaluatorTest, GraphInputsBindWithDefaultsAndTypeChecks) {
  Graph g;
  ASSERT_TRUE(g.add_input(GraphInput{"x", &value_type<double>(), "", {}}));
  ASSERT_TRUE(g.add_input(GraphInput{"y", &value_type<double>(), "", Value::make(10.0)}));
  const NodeId a = add(g, "test.Add");
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 0}, PortRef{a, 0}));
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 1}, PortRef{a, 1}));
  test::output(g, "sum", a);
  EXPECT_EQ(ev.evaluate(g, {{"x", Value::make(1.0)}}).output("sum")->get<double>(), 11.0);
  EXPECT_EQ(ev.evaluate(g, {{"x", Value::make(1.0)}, {"y", Value::make(2.0)}}).output("sum")->get<double>(), 3.0);

  EvalResult unbound = ev.evaluate(g, {});
  EXPECT_EQ(unbound.output("sum"), nullptr);
  ASSERT_FALSE(unbound.diagnostics.empty());
  EXPECT_EQ(unbound.diagnostics[0].to_string(), "error: node 1 (test.Add): input 'a': graph input 'x' is not bound and has no default");

  EvalResult wrong = ev.evaluate(g, {{"x", Value::make(std::string("1"))}, {"z", Value::make(1.0)}});
  EXPECT_FALSE(wrong.ok());
  std::string all;
  for (const Diagnostic& d : wrong.diagnostics) all += d.to_string() + "\n";
  EXPECT_NE(all.find("no graph input named 'z'"), std::string::npos) << all;
  EXPECT_NE(all.find("graph input 'x' takes float but was bound to string"), std::string::npos) << all;
}

TEST_F(EvaluatorTest, FailuresStayOnTheirBranch) {
  //  c(-1) -> fail -> add -> "bad"
  //  c(2)  -> add2 -> "good"
  Graph g;
  const NodeId neg = constant(g, -1);
  const NodeId f = add(g, "test.Fail");
  const NodeId a = add(g, "test.Add");
  link(g, neg, 0, f, 0);
  link(g, f, 0, a, 0);
  test::output(g, "bad", a);
  const NodeId two = constant(g, 2);
  const NodeId a2 = add(g, "test.Add");
  link(g, two, 0, a2, 0);
  test::output(g, "good", a2);
  EvalResult r = ev.evaluate(g, {});
  EXPECT_EQ(r.output("good")->get<double>(), 2.0);
  EXPECT_EQ(r.output("bad"), nullptr);
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "error: node 2 (test.Fail): failed on purpose");
  EXPECT_EQ(r.diagnostics[1].to_string(),
            "error: node 3 (test.Add): input failed: 'a' comes from node 2 (test.Fail), which has no result");
  EXPECT_EQ(r.stats.find({f})->outcome, NodeOutcome::kFailed);
  EXPECT_EQ(r.stats.find({a})->outcome, NodeOutcome::kInputFailed);

  // Errors are not cached: the failing node runs again.
  test::reset_evaluations();
  ev.evaluate(g, {});
  EXPECT_EQ(test::evaluations_of("test.Fail"), 1);
  EXPECT_EQ(test::evaluations_of("test.Add"), 0);

  // Exceptions become node errors too.
  ASSERT_TRUE(g.set_param(f, "how", Value::make(EnumValue{"throw"})));
  EvalResult thrown = ev.evaluate(g, {}, {"bad"});
  EXPECT_EQ(thrown.diagnostics[0].to_string(), "error: node 2 (test.Fail): thrown on purpose");

  // Running out of memory is said in words, with what to do.
  ASSERT_TRUE(g.set_param(f, "how", Value::make(EnumValue{"out_of_memory"})));
  EvalResult oom = ev.evaluate(g, {}, {"bad"});
  EXPECT_EQ(oom.diagnostics[0].to_string(), std::string("error: node 2 (test.Fail): ") + kOutOfMemory);
  EXPECT_EQ(oom.diagnostics[0].to_string().find("bad_alloc"), std::string::npos);
}

TEST_F(EvaluatorTest, WarningsSurviveTheCache) {
  Graph g;
  const NodeId zero = constant(g, 0);
  const NodeId f = add(g, "test.Fail");
  link(g, zero, 0, f, 0);
  test::output(g, "out", f);
  for (int i = 0; i < 2; ++i) {
    EvalResult r = ev.evaluate(g, {});
    ASSERT_TRUE(r.output("out"));
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].to_string(), "warning: node 2 (test.Fail): x is zero");
  }
  EXPECT_EQ(test::evaluations_of("test.Fail"), 1);
}

TEST_F(EvaluatorTest, PassThroughHandsOnTheInputHash) {
  Graph g;
  const NodeId c = constant(g, 4);
  const NodeId s = add(g, "test.Switch");
  link(g, c, 0, s, 0);
  test::output(g, "through", s);
  test::output(g, "direct", c);
  ASSERT_TRUE(g.set_param(s, "enabled", Value::make(false)));
  EvalResult r = ev.evaluate(g, {});
  EXPECT_EQ(r.outputs[0].hash, r.outputs[1].hash);
  EXPECT_EQ(r.output("through")->get<double>(), 4.0);
  EXPECT_EQ(test::evaluations_of("test.Switch"), 0);
  EXPECT_EQ(r.stats.find({s})->outcome, NodeOutcome::kPassThrough);
  ASSERT_TRUE(g.set_param(s, "enabled", Value::make(true)));
  EvalResult on = ev.evaluate(g, {});
  EXPECT_NE(on.outputs[0].hash, on.outputs[1].hash);
  EXPECT_EQ(on.output("through")->get<double>(), 8.0);
}

// A node that hands on one input (a building-type switch) needs nothing
// upstream of its other inputs: that branch is not even planned or hashed.
//   c ---------------- first
//                            pick -> "out"
//   size -> add(x2) -- second
TEST_F(EvaluatorTest, BranchesAPassThroughDoesNotTakeAreNotPlanned) {
  Graph g;
  const NodeId c = constant(g, 4);
  const NodeId size = add(g, "test.FileSize");
  const NodeId twice = add(g, "test.Add");
  const NodeId pick = add(g, "test.Pick");
  ASSERT_TRUE(g.add_input(GraphInput{"x", &value_type<double>(), "", Value::make(0.5)}));
  link(g, c, 0, pick, 0);
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 0}, PortRef{twice, 0}));
  link(g, twice, 0, pick, 1);
  ASSERT_TRUE(g.set_param(size, "path", Value::make(std::string("nowhere.txt"))));
  test::output(g, "out", pick);
  ASSERT_TRUE(g.add_output(GraphOutput{"size", &value_type<std::int64_t>(), ""}));  // planned only when asked for
  ASSERT_TRUE(g.connect(PortRef{size, 0}, PortRef{kGraphOutputs, 1}));
  test::file_size_hashes() = 0;
  const EvalResult first = ev.evaluate(g, {}, {"out"});
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(first.output("out")->get<double>(), 4.0);
  EXPECT_EQ(first.outputs[0].hash, ev.hash_outputs(g, {}, {"out"}).outputs[0].hash);
  EXPECT_EQ(test::evaluations(), 1);  // the constant
  ASSERT_TRUE(g.set_param(pick, "which", Value::make<std::int64_t>(1)));
  const EvalResult second = ev.evaluate(g, {}, {"out"});
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(second.output("out")->get<double>(), 0.5);
  EXPECT_EQ(test::evaluations_of("test.Add"), 1);
  EXPECT_EQ(test::evaluations_of("test.Pick"), 0);
  EXPECT_EQ(second.stats.find({pick})->outcome, NodeOutcome::kPassThrough);
  EXPECT_EQ(test::file_size_hashes(), 0);  // FileSize feeds neither: never planned
  (void)ev.hash_outputs(g, {}, {"size"});
  EXPECT_EQ(test::file_size_hashes(), 1);
  // A chosen input that is not connected: no pass-through, the usual checks.
  ASSERT_TRUE(g.disconnect(PortRef{pick, 1}));
  const EvalResult open = ev.evaluate(g, {}, {"out"});
  ASSERT_FALSE(open.diagnostics.empty());
  EXPECT_EQ(open.diagnostics[0].to_string(), "error: node 4 (test.Pick): input 'second' is not connected");
}

TEST_F(EvaluatorTest, HashesDependOnTheEngineSalt) {
  test::Diamond d = test::diamond();
  Evaluator other(cache, "test-engine-2");
  EXPECT_NE(ev.hash_outputs(d.g, {}).outputs[0].hash, other.hash_outputs(d.g, {}).outputs[0].hash);
  EXPECT_EQ(ev.hash_outputs(d.g, {}).outputs[0].hash, ev.evaluate(d.g, {}).outputs[0].hash);
  EXPECT_EQ(test::evaluations(), 7);  // hash_outputs computes nothing
}

// hash_outputs runs nothing but reports what would stop evaluate(), naming the node and its input;
// with assume_inputs_bound (checking a recipe before binding) only the unconnected input remains.
TEST_F(EvaluatorTest, HashOnlyRunsNameMissingInputs) {
  Graph g;
  ASSERT_TRUE(g.add_input(GraphInput{"x", &value_type<double>(), "", {}}));
  const NodeId add_node = add(g, "test.Add");
  const NodeId mul = add(g, "test.Mul");
  ASSERT_TRUE(g.connect(PortRef{kGraphInputs, 0}, PortRef{add_node, 0}));
  ASSERT_TRUE(g.connect(PortRef{add_node, 0}, PortRef{mul, 0}));  // mul's input b stays unconnected
  test::output(g, "sum", add_node);
  test::output(g, "product", mul);
  auto messages = [](const EvalResult& r) {
    std::vector<std::string> m;
    for (const Diagnostic& d : r.diagnostics) m.push_back(d.to_string());
    return m;
  };
  const EvalResult hashed = ev.hash_outputs(g, {});
  EXPECT_FALSE(hashed.ok());
  EXPECT_EQ(messages(hashed), (std::vector<std::string>{
                                  "error: node 1 (test.Add): input 'a': graph input 'x' is not bound and has no default",
                                  "error: node 2 (test.Mul): input 'b' is not connected"}));
  EXPECT_EQ(messages(ev.hash_outputs(g, {}, {"sum"})).size(), 1u);  // only what the request needs
  EXPECT_TRUE(ev.hash_outputs(g, {{"x", Value::make(1.0)}}, {"sum"}).diagnostics.empty());
  EXPECT_EQ(messages(ev.evaluate(g, {})), messages(hashed));  // the same words as a real evaluation
  EvalOptions before_binding;
  before_binding.assume_inputs_bound = true;
  EXPECT_EQ(messages(ev.hash_outputs(g, {}, {}, before_binding)),
            (std::vector<std::string>{"error: node 2 (test.Mul): input 'b' is not connected"}));
  EXPECT_EQ(test::evaluations(), 0);
}

TEST_F(EvaluatorTest, EditorStateIsNotHashed) {
  test::Diamond d = test::diamond();
  const Hash128 before = ev.hash_outputs(d.g, {}).outputs[0].hash;
  ASSERT_TRUE(d.g.set_editor_state(d.add1, EditorState{100, -50, "note", true}));
  d.g.metadata.name = "renamed";
  EXPECT_EQ(ev.hash_outputs(d.g, {}).outputs[0].hash, before);
}

TEST_F(EvaluatorTest, CancellationStopsAndCachesNothingPartial) {
  Graph g;
  const NodeId c = constant(g, 1);
  NodeId prev = c;
  for (int i = 0; i < 4; ++i) {
    const NodeId s = add(g, "test.Slow");
    ASSERT_TRUE(g.set_param(s, "steps", Value::make<std::int64_t>(100000)));
    link(g, prev, 0, s, 0);
    prev = s;
  }
  test::output(g, "out", prev);
  EvalOptions options;
  std::thread canceller([&] {
    while (test::evaluations_of("test.Slow") == 0) std::this_thread::yield();
    options.cancel.cancel();
  });
  EvalResult r = ev.evaluate(g, {}, {}, options);
  canceller.join();
  EXPECT_TRUE(r.cancelled);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.output("out"), nullptr);
  EXPECT_EQ(r.stats.count(NodeOutcome::kCancelled), 4u);
  EXPECT_EQ(test::evaluations_of("test.Slow"), 1);  // later nodes never started
  EXPECT_EQ(cache.counters().entries, 1u);          // only the constant
}

TEST_F(EvaluatorTest, CacheIsBoundedInBytes) {
  ResultCache small(4 * (ResultCache::kEntryOverhead + 64));
  Evaluator e(small, "x");
  Graph g = test::add_tree(16);
  EvalResult r = e.evaluate(g, {});
  ASSERT_TRUE(r.ok());
  const CacheCounters c = small.counters();
  EXPECT_LE(c.bytes, c.capacity);
  EXPECT_GT(c.evictions, 0u);
  EXPECT_LT(c.entries, 31u);
  // The most recent results are the ones kept: a re-evaluation hits at the root.
  test::reset_evaluations();
  e.evaluate(g, {});
  EXPECT_EQ(test::evaluations(), 0);
}

TEST_F(EvaluatorTest, ParallelAndSerialAgree) {
  Graph g = test::add_tree(200);
  EvalOptions serial;
  serial.parallel = false;
  ResultCache other(64 << 20);
  Evaluator e2(other, "test-engine-1");
  EvalResult a = ev.evaluate(g, {});
  EvalResult b = e2.evaluate(g, {}, {}, serial);
  ASSERT_TRUE(a.ok());
  EXPECT_EQ(a.output("root")->get<double>(), 199.0 * 200.0 / 2);
  EXPECT_EQ(a.output("root")->get<double>(), b.output("root")->get<double>());
  EXPECT_EQ(a.outputs[0].hash, b.outputs[0].hash);
}

TEST_F(EvaluatorTest, GroupsEvaluateWithExposedParametersAndShareTheCache) {
  auto body = std::make_shared<Graph>();
  ASSERT_TRUE(body->add_input(GraphInput{"x", &value_type<double>(), "", {}}));
  const NodeId inner = add(*body, "test.Add");
  ASSERT_TRUE(body->connect(PortRef{kGraphInputs, 0}, PortRef{inner, 0}));
  test::output(*body, "y", inner);
  ASSERT_TRUE(body->expose_param(ExposedParam{"factor", inner, 0}));

  Graph g;
  ASSERT_TRUE(g.add_group("scaler", body));
  const NodeId c = constant(g, 2);
  const NodeId g1 = g.add_group_node("scaler").value();
  const NodeId g2 = g.add_group_node("scaler").value();
  link(g, c, 0, g1, 0);
  link(g, c, 0, g2, 0);
  ASSERT_TRUE(g.set_param(g2, "factor", Value::make(5.0)));
  test::output(g, "one", g1);
  test::output(g, "five", g2);
  EvalResult r = ev.evaluate(g, {});
  ASSERT_TRUE(r.ok()) << r.diagnostics[0].to_string();
  EXPECT_EQ(r.output("one")->get<double>(), 2.0);
  EXPECT_EQ(r.output("five")->get<double>(), 10.0);
  EXPECT_NE(r.stats.find({g2, inner}), nullptr);  // inner nodes report under the instance's path

  // A second instance with the same inputs and parameters is a cache hit, not a recompute.
  const NodeId g3 = g.add_group_node("scaler").value();
  link(g, c, 0, g3, 0);
  test::output(g, "again", g3);
  test::reset_evaluations();
  EvalResult r2 = ev.evaluate(g, {}, {"again"});
  EXPECT_EQ(r2.output("again")->get<double>(), 2.0);
  EXPECT_EQ(test::evaluations(), 0);
}

TEST_F(EvaluatorTest, GroupsThatMultiplyAreRefusedNotExpanded) {
  // Level k holds 10 instances of level k-1, all summed: 10^7 constants after 7 levels.
  std::shared_ptr<Graph> level = std::make_shared<Graph>();
  test::output(*level, "v", constant(*level, 1));
  for (int k = 1; k <= 7; ++k) {
    auto next = std::make_shared<Graph>();
    ASSERT_TRUE(next->add_group("inner", level));
    NodeId sum = next->add_group_node("inner").value();
    for (int i = 1; i < 10; ++i) {
      const NodeId inst = next->add_group_node("inner").value();
      const NodeId a = add(*next, "test.Add");
      link(*next, sum, 0, a, 0);
      link(*next, inst, 0, a, 1);
      sum = a;
    }
    test::output(*next, "v", sum);
    level = next;
  }
  EvalOptions options;
  options.max_expanded_nodes = 20000;
  EvalResult r = ev.evaluate(*level, {}, {}, options);
  EXPECT_FALSE(r.ok());
  ASSERT_FALSE(r.diagnostics.empty());
  std::string all;
  for (const Diagnostic& d : r.diagnostics) all += d.to_string() + "\n";
  EXPECT_NE(all.find("the graph expands to more than 20000 nodes once its groups are flattened"), std::string::npos)
      << all.substr(0, 500);
}

// test.FileSize of data.txt in a folder of its own, the file holding 5 bytes.
class FileSizeGraphTest : public EvaluatorTest {
 protected:
  void SetUp() override {
    EvaluatorTest::SetUp();
    std::ofstream(dir_ / "data.txt") << "12345";
    const NodeId n = add(g_, "test.FileSize");
    ASSERT_TRUE(g_.set_param(n, "path", Value::make(std::string("data.txt"))));
    ASSERT_TRUE(g_.add_output(GraphOutput{"bytes", &value_type<std::int64_t>(), ""}));
    ASSERT_TRUE(g_.connect(PortRef{n, 0}, PortRef{kGraphOutputs, 0}));
    options_.folder = dir_.path();
  }
  std::int64_t bytes() { return ev.evaluate(g_, {}, {}, options_).output("bytes")->get<std::int64_t>(); }
  void rewrite(const std::string& text) { std::ofstream(dir_ / "data.txt") << text; }

  const test::ScratchDir dir_{"eval_file"};
  Graph g_;
  EvalOptions options_;
};

TEST_F(FileSizeGraphTest, NodesReadingFilesKeyOnTheFileState) {
  EXPECT_EQ(bytes(), 5);
  EXPECT_EQ(bytes(), 5);
  EXPECT_EQ(test::evaluations(), 1);
  rewrite("1234567");
  EXPECT_EQ(bytes(), 7);
  EXPECT_EQ(test::evaluations(), 2);
}

// A batch looks at each file once: a file edited while it runs keys (and
// makes) no building differently; the next batch sees the edit.
TEST_F(FileSizeGraphTest, ABatchKeysEveryBuildingOnTheFileVersionsItSawFirst) {
  options_.pin_files_for_a_batch();
  EXPECT_EQ(bytes(), 5);
  rewrite("1234567");
  EXPECT_EQ(bytes(), 5);
  EXPECT_EQ(test::evaluations(), 1);
  options_.pin_files_for_a_batch();
  EXPECT_EQ(bytes(), 7);
  EXPECT_EQ(test::evaluations(), 2);
}

TEST_F(EvaluatorTest, StatsPrintATable) {
  test::Diamond d = test::diamond();
  EvalResult r = ev.evaluate(d.g, {});
  std::ostringstream out;
  r.stats.print(out);
  const std::string text = out.str();
  EXPECT_NE(text.find("node"), std::string::npos);
  EXPECT_NE(text.find("test.Mul"), std::string::npos);
  EXPECT_NE(text.find("7 nodes: 7 computed, 0 cache hits"), std::string::npos) << text;
  for (const NodeStats& s : r.stats.nodes) EXPECT_EQ(s.memory, sizeof(double));
}

TEST_F(EvaluatorTest, PortRequestsPreviewAnyNode) {
  test::Diamond d = test::diamond();
  const PortRef ports[] = {PortRef{d.add2, 0}};
  EvalResult r = ev.evaluate_ports(d.g, {}, ports);
  ASSERT_EQ(r.outputs.size(), 1u);
  EXPECT_EQ(r.outputs[0].name, "6.sum");
  EXPECT_EQ(r.outputs[0].value.get<double>(), 7.0);
  EXPECT_EQ(test::evaluations(), 3);
}

TEST_F(EvaluatorTest, UnknownOutputsAndUnconnectedOutputsAreReported) {
  Graph g;
  ASSERT_TRUE(g.add_output(GraphOutput{"nothing", &value_type<double>(), ""}));
  EvalResult r = ev.evaluate(g, {}, {"nothing", "missing"});
  ASSERT_EQ(r.diagnostics.size(), 2u);
  EXPECT_EQ(r.diagnostics[0].to_string(), "error: the graph has no output named 'missing'");
  EXPECT_EQ(r.diagnostics[1].to_string(), "error: output 'nothing': nothing is connected");
}

}  // namespace
}  // namespace procex
