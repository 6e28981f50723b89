// graph_bench -- framework overhead of graph/ on a 1,000-node graph of trivial
// nodes (test.Add trees), so the figures are the evaluator's own cost.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include "graph/evaluator.h"
#include "tests/graph/test_graphs.h"

namespace procex {
namespace {

constexpr std::size_t kLeaves = 500;  // 2 * 500 - 1 = 999 nodes

struct Fixture {
  Graph g = test::add_tree(kLeaves);
  ResultCache cache{std::size_t{1} << 30};
  Evaluator ev{cache, "bench"};
  std::vector<PortRef> all_ports;
  Fixture() {
    for (const auto& [id, n] : g.nodes()) all_ports.push_back(PortRef{id, 0});
  }
};

void set_counters(benchmark::State& state, std::size_t nodes) {
  state.counters["nodes"] = static_cast<double>(nodes);
  // Seconds per node, printed with an SI prefix ("548ns").
  state.counters["per_node"] = benchmark::Counter(static_cast<double>(nodes),
                                                  benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

EvalOptions options_for(const benchmark::State& state) {
  EvalOptions o;
  o.parallel = state.range(0) != 0;
  return o;
}

// Every node computed: cache emptied before each evaluation.
void BM_FullEvaluation(benchmark::State& state) {
  Fixture f;
  const EvalOptions o = options_for(state);
  for (auto _ : state) {
    state.PauseTiming();
    f.cache.clear();
    state.ResumeTiming();
    EvalResult r = f.ev.evaluate(f.g, {}, {}, o);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, f.g.nodes().size());
  // What the cache charges per result, and what the heap really grows by.
  f.cache.clear();
  const std::size_t heap_before = mallinfo2().uordblks;
  f.ev.evaluate(f.g, {}, {}, o);
  const std::size_t heap_after = mallinfo2().uordblks;
  const CacheCounters c = f.cache.counters();
  state.counters["charged_bytes_per_result"] = static_cast<double>(c.bytes) / static_cast<double>(c.entries);
  state.counters["heap_bytes_per_result"] = static_cast<double>(heap_after - heap_before) / static_cast<double>(c.entries);
}

// One leaf parameter changes per iteration: only its path to the root (~10 nodes) recomputes.
void BM_LeafEdit(benchmark::State& state) {
  Fixture f;
  const EvalOptions o = options_for(state);
  f.ev.evaluate(f.g, {}, {}, o);
  const NodeId leaf = f.g.nodes().begin()->first;
  double v = 1e5;
  std::size_t computed = 0;
  for (auto _ : state) {
    state.PauseTiming();
    (void)f.g.set_param(leaf, "value", Value::make(v += 1));
    state.ResumeTiming();
    EvalResult r = f.ev.evaluate(f.g, {}, {}, o);
    computed = r.stats.computed();
    benchmark::DoNotOptimize(r);
  }
  state.counters["recomputed"] = static_cast<double>(computed);
  set_counters(state, f.g.nodes().size());
}

// Nothing changed: hashing the graph and one cache hit at the root.
void BM_FullyCached(benchmark::State& state) {
  Fixture f;
  const EvalOptions o = options_for(state);
  f.ev.evaluate(f.g, {}, {}, o);
  for (auto _ : state) {
    EvalResult r = f.ev.evaluate(f.g, {}, {}, o);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, f.g.nodes().size());
}

// Nothing changed, every node's output requested (an editor showing all previews):
// one cache lookup per node on top of hashing.
void BM_FullyCachedAllPorts(benchmark::State& state) {
  Fixture f;
  const EvalOptions o = options_for(state);
  f.ev.evaluate_ports(f.g, {}, f.all_ports, o);
  for (auto _ : state) {
    EvalResult r = f.ev.evaluate_ports(f.g, {}, f.all_ports, o);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, f.g.nodes().size());
}

BENCHMARK(BM_FullEvaluation)->Arg(0)->Arg(1)->ArgName("parallel")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_LeafEdit)->Arg(0)->Arg(1)->ArgName("parallel")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FullyCached)->Arg(0)->Arg(1)->ArgName("parallel")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FullyCachedAllPorts)->Arg(0)->Arg(1)->ArgName("parallel")->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace procex

BENCHMARK_MAIN();
