#include "graph/evaluator.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <new>
#include <tuple>
#include <unordered_map>
#include <utility>

#include <tbb/task_group.h>

#include "graph/expression_value.h"

namespace procex {

namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t ns_since(Clock::time_point t0) {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0).count());
}

constexpr std::size_t kMaxGroupDepth = 64;
constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// Where an input's value comes from once groups are flattened and
// pass-throughs followed.
struct Source {
  enum Kind { kUnconnected, kNode, kValue, kMissing } kind = kUnconnected;
  std::size_t node = kNone;  // kNode: plan index
  std::uint32_t port = 0;    // kNode: output index
  // kValue: the top graph's input of this index, whose value and hash each run
  // binds (Run::inputs_), so that a plan serves other bindings; kNone: `value`
  // and `hash` below (a group input's default).
  std::size_t input = kNone;
  Value value;
  Hash128 hash;
  std::string why;  // kMissing: for the consumer's error
};

// kHashed: needed by a hash-only request, nothing wrong found.
enum class State { kPending, kHashed, kHit, kCompute, kDone, kFailed, kInputFailed, kCancelled };

// One node as planning made it: the same for every run of its plan.
struct PlanNode {
  NodePath path;
  const Node* node = nullptr;
  std::vector<Value> overridden;  // exposed parameters of enclosing groups applied; empty: none
  std::vector<Source> inputs;
  // The key fed with the salt, the type, the parameters, the expressions and
  // the files (hash_extra): its inputs' hashes, known in each run, finish it.
  Hasher key_prefix;
  std::vector<std::optional<std::uint32_t>> passes;  // output i hands on input *passes[i]
  std::string static_error;                           // found while planning: never evaluated

  const std::vector<Value>& params() const { return overridden.empty() ? node->params : overridden; }
  const NodeDecl& decl() const { return node->decl(); }
  // Never evaluated: consumers read straight from its inputs.
  bool passes_all() const {
    return !passes.empty() && std::all_of(passes.begin(), passes.end(), [](const auto& p) { return p.has_value(); });
  }
};

// A request planned: the graph flattened, parameters and expressions
// evaluated, keys hashed up to the bound inputs. Immutable, so that runs whose
// planning would read the same values share it (PlanMemo).
struct Plan {
  std::shared_ptr<const Graph> graph;  // kept in a PlanMemo: the graph its nodes point into, a copy of the caller's
  std::vector<PlanNode> nodes;         // upstream before downstream
  std::vector<Source> wanted;          // what feeds each requested port
  std::vector<Diagnostic> warnings;    // the parameters' (an expression's)
  std::vector<std::size_t> by_path;    // node indexes in path order: the statistics' order
  // What planning read besides the graph, the request and how each graph
  // input is bound (PlanMemo's keys): the attributes attr() read, by name, and
  // the graph inputs whose values expressions read, by index.
  std::vector<std::string> attributes_read;
  std::vector<std::size_t> inputs_read;
};

// One graph being flattened: the recipe itself, or the body of one group instance.
struct Frame {
  const Graph* graph = nullptr;
  NodePath prefix;
  std::vector<Source> inputs;                                     // what feeds each graph input
  std::unordered_map<NodeId, std::vector<std::pair<std::uint32_t, Value>>> overrides;  // node -> (param, value)
  std::unordered_map<NodeId, std::size_t> plan_index;             // regular nodes
  std::unordered_map<NodeId, std::vector<Source>> group_outputs;  // group instances
};

// A bound graph input's value: a run's own.
const Value& value_of(const Source& s, const std::vector<Source>& inputs) {
  return s.input == kNone ? s.value : inputs[s.input].value;
}

// Phase 1: flattens what the requested ports of the top graph need.
class Planner {
 public:
  Planner(const Hash128& salt, const EvalOptions& options, int level, const std::vector<Source>& inputs, Plan& plan)
      : salt_(salt), options_(options), level_(level), inputs_(inputs), plan_(plan) {}

  void plan(const Graph& g, std::span<const PortRef> ports) {
    Frame top;
    top.graph = &g;
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
      Source s;
      s.kind = inputs_[i].kind;
      s.why = inputs_[i].why;
      if (s.kind == Source::kValue) s.input = i;
      top.inputs.push_back(std::move(s));
    }
    std::vector<NodeId> starts;
    for (const PortRef& p : ports)
      if (p.node != kGraphInputs) starts.push_back(p.node);
    flatten(top, starts, 0);
    for (const PortRef& p : ports) plan_.wanted.push_back(resolve(top, p));
    plan_.by_path.resize(plan_.nodes.size());
    for (std::size_t i = 0; i < plan_.by_path.size(); ++i) plan_.by_path[i] = i;
    std::sort(plan_.by_path.begin(), plan_.by_path.end(),
              [this](std::size_t a, std::size_t b) { return plan_.nodes[a].path < plan_.nodes[b].path; });
  }

 private:
  // What feeds the output port `p` of frame `f` (after flatten()).
  Source resolve(const Frame& f, PortRef p) const {
    if (p.node == kGraphInputs) return p.port < f.inputs.size() ? f.inputs[p.port] : Source{};
    if (auto g = f.group_outputs.find(p.node); g != f.group_outputs.end()) return g->second.at(p.port);
    auto it = f.plan_index.find(p.node);
    if (it == f.plan_index.end()) {
      Source s;
      s.kind = Source::kMissing;
      s.why = "no node " + std::to_string(p.node);
      return s;
    }
    const PlanNode& n = plan_.nodes[it->second];
    if (p.port >= n.passes.size()) return Source{};
    if (n.passes[p.port]) return n.inputs[*n.passes[p.port]];
    Source s;
    s.kind = Source::kNode;
    s.node = it->second;
    s.port = p.port;
    return s;
  }

  Source resolve_input(const Frame& f, PortRef to) const {
    auto it = f.graph->links().find(to);
    if (it == f.graph->links().end()) return Source{};
    return resolve(f, it->second);
  }

  // Visits the nodes `starts` need in dependency order (iteratively: chains
  // may be long), creating plan nodes.
  void flatten(Frame& f, const std::vector<NodeId>& starts, std::size_t depth) {
    const auto& links = f.graph->links();
    std::vector<std::pair<NodeId, bool>> stack;
    std::unordered_map<NodeId, bool> seen;  // true once emitted
    for (NodeId s : starts) stack.emplace_back(s, false);
    while (!stack.empty()) {
      auto [id, expanded] = stack.back();
      if (expanded) {
        stack.pop_back();
        bool& emitted = seen[id];
        if (!emitted) {
          emitted = true;
          emit(f, id, depth);
        }
        continue;
      }
      if (seen.count(id)) {
        stack.pop_back();
        continue;
      }
      seen[id] = false;
      stack.back().second = true;
      const std::optional<std::uint32_t> only = passed_input(f, id);
      for (auto it = links.lower_bound(PortRef{id, 0}); it != links.end() && it->first.node == id; ++it)
        if (it->second.node != kGraphInputs && !seen.count(it->second.node) && (!only || it->first.port == *only))
          stack.emplace_back(it->second.node, false);
    }
  }

  // A node's parameters as they are in frame f: exposed parameters of
  // enclosing groups applied, expressions evaluated. `storage` holds them when
  // they differ from the node's own; a parameter without a value (a failed
  // expression, a result out of range) sets `error`. Warnings go to `warnings`
  // when given.
  const std::vector<Value>& params_in(const Frame& f, const Node& node, std::vector<Value>& storage, std::string& error,
                                      std::vector<std::string>* warnings = nullptr) {
    auto o = f.overrides.find(node.id);
    if (o == f.overrides.end() && node.expressions.empty()) return node.params;
    storage = node.params;
    for (std::uint32_t p = 0; p < storage.size() && error.empty(); ++p) {
      if (o == f.overrides.end() && !node.expressions.count(p)) continue;
      try {
        storage[p] = param_value(f, node, p, 0, warnings);
      } catch (const std::exception& e) {
        error = "parameter '" + node.decl().params()[p].name + "': " + e.what();
      }
    }
    return storage;
  }

  // Parameter p of `node` in frame f (throws, naming what is wrong).
  Value param_value(const Frame& f, const Node& node, std::uint32_t p, std::size_t depth,
                    std::vector<std::string>* warnings) {
    if (auto o = f.overrides.find(node.id); o != f.overrides.end())
      for (auto it = o->second.rbegin(); it != o->second.rend(); ++it)
        if (it->first == p) return it->second;
    auto e = node.expressions.find(p);
    if (e == node.expressions.end()) return node.params[p];
    if (depth > kMaxGroupDepth) throw std::runtime_error("expressions read each other in a cycle");
    const Expression& expr = *e->second;
    const ParamDecl& decl = node.decl().params()[p];
    Expression::Env env;
    env.name = [&](std::string_view name) { return name_value(f, name, depth, warnings); };
    env.attribute = [this](std::string_view key) -> const std::string* {
      if (std::find(plan_.attributes_read.begin(), plan_.attributes_read.end(), key) == plan_.attributes_read.end())
        plan_.attributes_read.emplace_back(key);
      auto a = options_.attributes.find(key);
      return a == options_.attributes.end() ? nullptr : &a->second;
    };
    if (warnings) env.warn = [&](std::string m) { warnings->push_back("parameter '" + decl.name + "': " + std::move(m)); };
    Result<Value> v = from_expr_value(expr.evaluate(env), *decl.type);
    if (!v) throw std::runtime_error(v.message());
    if (Status s = decl.check(*v); !s) throw std::runtime_error("'" + expr.text() + "' gives a value the parameter refuses: " + s.message());
    return *v;
  }

  // What an expression name reads in frame f: a graph input known before
  // evaluation, or an exposed parameter.
  ExprValue name_value(const Frame& f, std::string_view name, std::size_t depth, std::vector<std::string>* warnings) {
    std::string q = "'";  // appended, not added: GCC 12's -Wrestrict misreads '"x" + std::string(...)' here
    q.append(name).append("'");
    if (auto i = f.graph->input_index(name)) {
      const Source& s = *i < f.inputs.size() ? f.inputs[*i] : Source{};
      if (s.input != kNone &&
          std::find(plan_.inputs_read.begin(), plan_.inputs_read.end(), s.input) == plan_.inputs_read.end())
        plan_.inputs_read.push_back(s.input);
      const Value& value = value_of(s, inputs_);
      if (s.kind == Source::kValue && value.empty()) {  // assume_inputs_bound: any value of the type will do
        const ExprType t = expression_type(*f.graph->inputs()[*i].type).value_or(ExprType::kNumber);
        return t == ExprType::kNumber ? ExprValue(0.0) : t == ExprType::kBool ? ExprValue(false) : ExprValue(std::string());
      }
      if (s.kind == Source::kValue && expression_type(*value.type())) return to_expr_value(value);
      if (s.kind == Source::kNode)
        throw ExprError("input " + q + " is fed by a node's output, known only once the graph runs; expressions read "
                        "values known before: the recipe's inputs, exposed parameters and attr()");
      throw ExprError("input " + q + " has no value" + (s.why.empty() ? "" : ": " + s.why));
    }
    for (const ExposedParam& e : f.graph->exposed_params()) {
      if (e.name != name) continue;
      try {
        return to_expr_value(param_value(f, *f.graph->node(e.node), e.param, depth + 1, warnings));
      } catch (const std::exception& err) {
        throw ExprError("exposed parameter " + q + ": " + err.what());
      }
    }
    throw ExprError("no graph input or exposed parameter named " + q + " here");
  }

  // Whether a node of this declaration may hand an input on: by its
  // parameters, or below its level of detail.
  bool hands_on(const NodeDecl& decl) const {
    return decl.pass_through() || (decl.detail_level() > level_ && !decl.inputs().empty());
  }
  // The input output `o` hands on, if any. Below its level of detail a node's
  // outputs of its first input's type hand that input on; its other outputs
  // (Mesh Placement's counts) are still computed for whoever reads them.
  std::optional<std::size_t> forwarded(const NodeDecl& decl, const std::vector<Value>& params, std::size_t o) const {
    if (decl.detail_level() > level_ && !decl.inputs().empty() && decl.outputs()[o].type == decl.inputs()[0].type)
      return 0;
    if (decl.pass_through()) return decl.pass_through()(params, o);
    return std::nullopt;
  }

  // The input that every output of node `id` hands on, when its parameters
  // say so and that input is linked (a Switch): nothing upstream of its other
  // inputs is needed, so none of it is planned or hashed.
  std::optional<std::uint32_t> passed_input(const Frame& f, NodeId id) {
    const Node* node = f.graph->node(id);
    if (!node || node->type->is_group() || !hands_on(node->decl())) return std::nullopt;
    std::vector<Value> storage;
    std::string error;
    const std::vector<Value>& params = params_in(f, *node, storage, error);
    if (!error.empty()) return std::nullopt;
    std::optional<std::size_t> only;
    for (std::size_t o = 0; o < node->decl().outputs().size(); ++o) {
      const std::optional<std::size_t> p = forwarded(node->decl(), params, o);
      if (!p || (only && *p != *only)) return std::nullopt;
      only = p;
    }
    if (!only || *only >= node->decl().inputs().size()) return std::nullopt;
    const auto input = static_cast<std::uint32_t>(*only);
    if (!f.graph->links().count(PortRef{id, input})) return std::nullopt;
    return input;
  }

  void emit(Frame& f, NodeId id, std::size_t depth) {
    const Node* node = f.graph->node(id);
    if (!node) return;  // a dangling request; resolve() reports it
    const NodeDecl& decl = node->decl();
    NodePath path = f.prefix;
    path.push_back(id);
    std::vector<Value> overridden;
    std::string param_error;
    std::vector<std::string> param_warnings;
    params_in(f, *node, overridden, param_error, &param_warnings);
    for (std::string& w : param_warnings) plan_.warnings.push_back({Severity::kWarning, path, node->type->name(), std::move(w)});
    if (node->type->is_group()) {
      emit_group(f, *node, std::move(path), overridden.empty() ? node->params : overridden, param_error, depth);
      return;
    }
    PlanNode n;
    n.path = std::move(path);
    n.node = node;
    n.overridden = std::move(overridden);
    n.static_error = std::move(param_error);
    Hasher& h = n.key_prefix;
    h.hash(salt_).hash(node->type->key);
    for (const Value& v : n.params()) v.hash(h);
    for (const auto& [p, e] : node->expressions) h.u64(p).str(e->text());
    if (decl.hash_extra()) decl.hash_extra()(n.params(), options_.folder, options_.file_versions.get(), h);
    n.inputs.reserve(decl.inputs().size());
    const std::optional<std::uint32_t> only = passed_input(f, id);
    for (std::uint32_t i = 0; i < decl.inputs().size(); ++i) {
      if (only && i != *only) {  // not planned (flatten): never read, since every output passes *only on
        n.inputs.emplace_back();
        continue;
      }
      Source s = resolve_input(f, PortRef{id, i});
      const std::string& name = decl.inputs()[i].name;
      if (s.kind == Source::kUnconnected && !decl.inputs()[i].optional) {
        s.kind = Source::kMissing;
        s.why = "input '" + name + "' is not connected";
        if (n.static_error.empty()) n.static_error = s.why;
      }
      if (s.kind == Source::kMissing && n.static_error.empty()) n.static_error = "input '" + name + "': " + s.why;
      n.inputs.push_back(std::move(s));
    }
    if (only && n.static_error.empty() && n.inputs[*only].kind != Source::kNode && n.inputs[*only].kind != Source::kValue)
      n.static_error = "input '" + decl.inputs()[*only].name + "' has no value";  // and the others were not planned
    const std::size_t outs = decl.outputs().size();
    n.passes.resize(outs);
    for (std::uint32_t o = 0; o < outs; ++o) {
      const std::optional<std::size_t> pass = forwarded(decl, n.params(), o);
      if (pass && *pass < n.inputs.size() &&
          (n.inputs[*pass].kind == Source::kNode || n.inputs[*pass].kind == Source::kValue))
        n.passes[o] = static_cast<std::uint32_t>(*pass);
    }
    f.plan_index.emplace(id, plan_.nodes.size());
    plan_.nodes.push_back(std::move(n));
  }

  void emit_group(Frame& f, const Node& node, NodePath path, const std::vector<Value>& params,
                  const std::string& param_error, std::size_t depth) {
    const Graph& body = *node.type->body;
    std::vector<Source>& outs = f.group_outputs[node.id];
    const bool too_deep = depth + 1 > kMaxGroupDepth;
    if (!param_error.empty() || too_deep || ++expanded_ + plan_.nodes.size() > options_.max_expanded_nodes) {
      Source s;
      s.kind = Source::kMissing;
      s.why = !param_error.empty() ? "group node " + to_string(path) + ": " + param_error
              : too_deep ? "groups nested deeper than " + std::to_string(kMaxGroupDepth) + " at node " + to_string(path)
                         : "the graph expands to more than " + std::to_string(options_.max_expanded_nodes) +
                               " nodes once its groups are flattened (at group node " + to_string(path) + ")";
      outs.assign(body.outputs().size(), s);
      return;
    }
    Frame inner;
    inner.graph = &body;
    inner.prefix = path;
    for (std::uint32_t i = 0; i < body.inputs().size(); ++i) {
      Source s = resolve_input(f, PortRef{node.id, i});
      if (s.kind == Source::kUnconnected) {
        const GraphInput& in = body.inputs()[i];
        if (in.default_value.empty()) {
          s.kind = Source::kMissing;
          s.why = "input '" + in.name + "' of group node " + to_string(path) + " is not connected";
        } else {
          s.kind = Source::kValue;
          s.value = in.default_value;
          s.hash = in.default_value.content_hash();
        }
      }
      inner.inputs.push_back(std::move(s));
    }
    // Overrides from further out take precedence over this instance's own values.
    const auto& exposed = body.exposed_params();
    for (std::size_t k = 0; k < exposed.size() && k < params.size(); ++k)
      inner.overrides[exposed[k].node].emplace_back(exposed[k].param, params[k]);
    std::vector<NodeId> starts;
    std::vector<PortRef> out_sources;
    for (std::uint32_t o = 0; o < body.outputs().size(); ++o) {
      auto src = body.source(PortRef{kGraphOutputs, o});
      out_sources.push_back(src.value_or(PortRef{kGraphInputs, 0xFFFFFFFFu}));
      if (src && src->node != kGraphInputs) starts.push_back(src->node);
    }
    flatten(inner, starts, depth + 1);
    outs.clear();
    for (std::uint32_t o = 0; o < out_sources.size(); ++o) {
      Source s = resolve(inner, out_sources[o]);
      if (s.kind == Source::kUnconnected) {
        s.kind = Source::kMissing;
        s.why = "output '" + body.outputs()[o].name + "' of group node " + to_string(path) + " is not connected inside";
      }
      outs.push_back(std::move(s));
    }
  }

  Hash128 salt_;
  const EvalOptions& options_;
  const int level_;  // of detail
  const std::vector<Source>& inputs_;
  Plan& plan_;
  std::size_t expanded_ = 0;  // group instances flattened so far
};

// One node in one run of a plan.
struct NodeRun {
  Hash128 key;
  std::vector<Hash128> out_hash;
  State state = State::kPending;
  std::vector<Value> outputs;
  std::vector<std::string> warnings;
  std::string error;  // why it failed while running; empty: its plan node's static error, if any
  std::vector<std::size_t> dependents;
  std::atomic<int> pending{0};
  std::uint64_t time_ns = 0;
};

// A plan run with one set of bound inputs: keys finished (phase 1's end),
// then phases 2 and 3.
class Run {
 public:
  Run(ResultCache& cache, const EvalOptions& options, EvalResult& result, const Plan& plan, std::vector<Source> inputs)
      : cache_(cache), options_(options), result_(result), plan_(plan), inputs_(std::move(inputs)), runs_(plan.nodes.size()) {
    for (std::size_t i = 0; i < plan_.nodes.size(); ++i) {
      const PlanNode& p = plan_.nodes[i];
      NodeRun& r = runs_[i];
      Hasher h = p.key_prefix;
      for (const Source& s : p.inputs)
        if (s.kind == Source::kNode || s.kind == Source::kValue) h.hash(hash_of(s));
        else h.u64(0x9e3779b97f4a7c15ull + s.kind);
      r.key = h.result();
      r.out_hash.resize(p.passes.size());
      for (std::uint32_t o = 0; o < p.passes.size(); ++o)
        r.out_hash[o] = p.passes[o] ? hash_of(p.inputs[*p.passes[o]]) : Hasher().hash(r.key).u64(o).result();
    }
  }

  // Hash-only runs: marks the nodes the request needs, so that those whose
  // inputs are missing (unbound, unconnected) report it as compute() would.
  void check() { walk(false); }

  // Phase 2 and 3: finds what is not cached and computes it.
  void compute() {
    const std::vector<std::size_t> to_run = walk(true);
    std::vector<std::size_t> ready;
    for (std::size_t i : to_run) {
      std::vector<std::size_t> deps;
      for (const Source& s : plan_.nodes[i].inputs)
        if (s.kind == Source::kNode && runs_[s.node].state == State::kCompute) deps.push_back(s.node);
      std::sort(deps.begin(), deps.end());
      deps.erase(std::unique(deps.begin(), deps.end()), deps.end());
      runs_[i].pending.store(static_cast<int>(deps.size()), std::memory_order_relaxed);
      for (std::size_t d : deps) runs_[d].dependents.push_back(i);
      if (deps.empty()) ready.push_back(i);
    }
    if (options_.parallel) {
      tbb::task_group tg;
      for (std::size_t i : ready) tg.run([this, i, &tg] { run_parallel(i, tg); });
      tg.wait();
    } else {
      std::vector<std::size_t> queue = ready;
      while (!queue.empty()) {
        const std::size_t i = queue.back();
        queue.pop_back();
        evaluate_node(i);
        for (std::size_t d : runs_[i].dependents)
          if (runs_[d].pending.fetch_sub(1) == 1) queue.push_back(d);
      }
    }
  }

  // Values, statistics and diagnostics into the result.
  void report(const std::vector<std::string>& names) {
    for (std::size_t k = 0; k < plan_.wanted.size(); ++k) {
      const Source& s = plan_.wanted[k];
      OutputResult r{names[k], {}, s.kind == Source::kNode || s.kind == Source::kValue ? hash_of(s) : s.hash};
      if (s.kind == Source::kValue) r.value = value_of(s, inputs_);
      if (s.kind == Source::kNode) {
        const NodeRun& n = runs_[s.node];
        if (n.state == State::kHit || n.state == State::kDone) r.value = n.outputs[s.port];
      }
      if (s.kind == Source::kMissing || s.kind == Source::kUnconnected)
        result_.diagnostics.push_back({Severity::kError, {}, {}, "output '" + names[k] + "': " +
                                                                   (s.why.empty() ? "nothing is connected" : s.why)});
      result_.outputs.push_back(std::move(r));
    }
    for (std::size_t i : plan_.by_path) report_node(i);  // in path order, as NodeStats are kept
    result_.cancelled = options_.cancel.cancelled();
  }

 private:
  Hash128 hash_of(const Source& s) const {
    if (s.kind == Source::kNode) return runs_[s.node].out_hash[s.port];
    return s.input == kNone ? s.hash : inputs_[s.input].hash;
  }

  // From the requested outputs towards the inputs: nodes with a static error
  // fail; with `use_cache`, cache hits stop the walk and the nodes to compute
  // are returned; without, every needed node is only marked as hashed.
  std::vector<std::size_t> walk(bool use_cache) {
    std::vector<std::size_t> stack;
    for (const Source& s : plan_.wanted)
      if (s.kind == Source::kNode) stack.push_back(s.node);
    std::vector<std::size_t> to_run;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      const PlanNode& p = plan_.nodes[i];
      NodeRun& n = runs_[i];
      if (n.state != State::kPending) continue;
      if (!p.static_error.empty()) {
        n.state = State::kFailed;
        continue;
      }
      if (!use_cache) {
        n.state = State::kHashed;
      } else if (CachedOutputs hit = cache_.find(n.key)) {
        n.state = State::kHit;
        const std::size_t count = p.decl().outputs().size();
        n.outputs.assign(hit->begin(), hit->begin() + static_cast<std::ptrdiff_t>(count));
        if (hit->size() > count) n.warnings = hit->back().get<std::vector<std::string>>();
        continue;
      } else {
        n.state = State::kCompute;
        to_run.push_back(i);
      }
      for (const Source& s : p.inputs)
        if (s.kind == Source::kNode) stack.push_back(s.node);
    }
    return to_run;
  }

  void run_parallel(std::size_t i, tbb::task_group& tg) {
    evaluate_node(i);
    for (std::size_t d : runs_[i].dependents)
      if (runs_[d].pending.fetch_sub(1, std::memory_order_acq_rel) == 1) tg.run([this, d, &tg] { run_parallel(d, tg); });
  }

  void evaluate_node(std::size_t i) {
    const PlanNode& p = plan_.nodes[i];
    NodeRun& n = runs_[i];
    const NodeDecl& decl = p.decl();
    std::vector<Value> inputs(p.inputs.size());
    for (std::size_t k = 0; k < p.inputs.size(); ++k) {
      const Source& s = p.inputs[k];
      if (s.kind == Source::kValue) inputs[k] = value_of(s, inputs_);
      if (s.kind != Source::kNode) continue;
      const NodeRun& up = runs_[s.node];
      if (up.state == State::kCancelled) {
        n.state = State::kCancelled;
        return;
      }
      if (up.state != State::kHit && up.state != State::kDone) {
        const PlanNode& from = plan_.nodes[s.node];
        n.state = State::kInputFailed;
        n.error = "input failed: '" + decl.inputs()[k].name + "' comes from node " + to_string(from.path) + " (" +
                  from.node->type->name() + "), which has no result";
        return;
      }
      inputs[k] = up.outputs[s.port];
      const ValueType* want = decl.inputs()[k].type;
      if (!want->is_any() && inputs[k].type() != want) {
        n.state = State::kFailed;
        n.error = "input '" + decl.inputs()[k].name + "' takes " + want->name() + " but received " +
                  inputs[k].type()->name();
        return;
      }
    }
    if (options_.cancel.cancelled()) {
      n.state = State::kCancelled;
      return;
    }
    EvalContext ctx(decl, p.params(), inputs, options_.cancel, options_.folder, options_.allowed_folders,
                    options_.resolved_paths.get(), options_.file_versions.get());
    const auto t0 = Clock::now();
    try {
      p.node->type->evaluate(ctx);
    } catch (const Cancelled&) {
      n.state = State::kCancelled;
    } catch (const std::bad_alloc&) {  // its what() says nothing a user can act on
      ctx.error(kOutOfMemory);
    } catch (const std::exception& e) {
      ctx.error(e.what());
    } catch (...) {
      ctx.error("unknown exception");
    }
    n.time_ns = ns_since(t0);
    if (n.state == State::kCancelled || options_.cancel.cancelled()) {
      n.state = State::kCancelled;
      return;
    }
    for (std::size_t o = 0; o < ctx.outputs().size() && !ctx.failed(); ++o) {
      const Value& v = ctx.outputs()[o];
      const PortDecl& port = decl.outputs()[o];
      if (v.empty()) ctx.error("output '" + port.name + "' was not set (a bug in the node)");
      else if (!port.type->is_any() && v.type() != port.type)
        ctx.error("output '" + port.name + "' is declared " + port.type->name() + " but got " + v.type()->name() +
                  " (a bug in the node)");
    }
    std::vector<std::string> warnings;
    std::string error;
    for (const auto& [severity, message] : ctx.messages()) {
      if (severity == Severity::kWarning) warnings.push_back(message);
      else error += (error.empty() ? "" : "; ") + message;
    }
    n.warnings = warnings;
    if (ctx.failed()) {
      n.state = State::kFailed;
      n.error = error;
      return;
    }
    n.outputs = std::move(ctx.outputs());
    n.state = State::kDone;
    std::vector<Value> entry = n.outputs;
    if (!warnings.empty()) entry.push_back(Value::make(std::move(warnings)));
    cache_.insert(n.key, std::move(entry));
  }

  void report_node(std::size_t i) {
    const PlanNode& p = plan_.nodes[i];
    const NodeRun& n = runs_[i];
    const std::string& type = p.node->type->name();
    if (p.passes_all()) {
      result_.stats.nodes.push_back(NodeStats{p.path, type, NodeOutcome::kPassThrough, n.key, 0, 0, p.overridden});
      return;
    }
    NodeOutcome outcome = NodeOutcome::kCancelled;
    switch (n.state) {
      case State::kPending: return;  // not needed: upstream of a cache hit, or only passed through
      case State::kHashed: return;
      case State::kHit: outcome = NodeOutcome::kCacheHit; break;
      case State::kDone: outcome = NodeOutcome::kComputed; break;
      case State::kFailed: outcome = NodeOutcome::kFailed; break;
      case State::kInputFailed: outcome = NodeOutcome::kInputFailed; break;
      case State::kCompute:  // never started: cancelled before its turn
      case State::kCancelled: outcome = NodeOutcome::kCancelled; break;
    }
    std::size_t memory = 0;
    for (const Value& v : n.outputs) memory += v.memory_size();
    result_.stats.nodes.push_back(NodeStats{p.path, type, outcome, n.key, n.time_ns, memory, p.overridden});
    for (const std::string& w : n.warnings) result_.diagnostics.push_back({Severity::kWarning, p.path, type, w});
    if (outcome == NodeOutcome::kFailed || outcome == NodeOutcome::kInputFailed)
      result_.diagnostics.push_back({Severity::kError, p.path, type, n.error.empty() ? p.static_error : n.error});
  }

  ResultCache& cache_;
  const EvalOptions& options_;
  EvalResult& result_;
  const Plan& plan_;
  const std::vector<Source> inputs_;  // the top graph's, bound (bind_inputs)
  std::vector<NodeRun> runs_;         // by plan index
};

// The top graph's inputs as `bindings` bind them, warning of bindings that
// name no input and of values of the wrong type.
std::vector<Source> bind_inputs(const Graph& g, const Bindings& bindings, const EvalOptions& options,
                                std::vector<Diagnostic>& diagnostics) {
  auto warn = [&](std::string message) { diagnostics.push_back({Severity::kWarning, {}, {}, std::move(message)}); };
  for (const auto& [name, v] : bindings)
    if (!g.input_index(name)) warn("no graph input named '" + name + "'; the binding is ignored");
  std::vector<Source> out;
  out.reserve(g.inputs().size());
  for (const GraphInput& in : g.inputs()) {
    Source& s = out.emplace_back();
    auto it = bindings.find(in.name);
    const Value* v = it != bindings.end() ? &it->second : (in.default_value.empty() ? nullptr : &in.default_value);
    if ((!v || v->empty()) && options.assume_inputs_bound) {
      s.kind = Source::kValue;  // no value: only hash_outputs may use this option
      s.hash = Hasher().str("unbound graph input").str(in.name).result();
    } else if (!v || v->empty()) {
      s.kind = Source::kMissing;
      s.why = "graph input '" + in.name + "' is not bound and has no default";
    } else if (!in.type->is_any() && v->type() != in.type) {
      s.kind = Source::kMissing;
      s.why = "graph input '" + in.name + "' takes " + in.type->name() + " but was bound to " + v->type()->name();
      warn(s.why);
    } else {
      s.kind = Source::kValue;
      s.value = *v;
      s.hash = v->content_hash();
    }
  }
  return out;
}

// What every plan for a request reads besides the graph: the ports, the
// options planning reads, the level of detail and how each graph input is
// bound (its value aside).
Hash128 request_key(const Hash128& salt, std::span<const PortRef> ports, const EvalOptions& options, int level,
                    const std::vector<Source>& inputs) {
  Hasher h;
  h.hash(salt).u64(static_cast<std::uint64_t>(level)).boolean(options.assume_inputs_bound).u64(options.max_expanded_nodes);
  h.str(options.folder.native()).u64(reinterpret_cast<std::uintptr_t>(options.file_versions.get()));
  h.u64(ports.size());
  for (const PortRef& p : ports) h.u64(p.node).u64(p.port);
  for (const Source& s : inputs) h.u64(s.kind).str(s.why);
  return h.result();
}

// That and the values a plan's planning read (Plan::attributes_read,
// inputs_read) as this run binds them: runs with equal keys plan alike.
Hash128 trace_key(const Hash128& request, const std::vector<std::string>& attributes,
                  const std::vector<std::size_t>& inputs_read, const EvalOptions& options,
                  const std::vector<Source>& inputs) {
  Hasher h;
  h.hash(request);
  for (const std::string& name : attributes) {
    const auto a = options.attributes.find(name);
    if (a == options.attributes.end()) h.u64(0);
    else h.u64(1).str(a->second);
  }
  for (std::size_t i : inputs_read) h.hash(inputs[i].hash);
  return h.result();
}

// The values of g's exposed parameters: where copies of one recipe set for
// different features differ (a PlanMemo's first look).
Hash128 exposed_key(const Graph& g) {
  Hasher h;
  for (const ExposedParam& e : g.exposed_params()) {
    const Node& node = *g.node(e.node);
    if (auto x = node.expressions.find(e.param); x != node.expressions.end()) h.u64(1).str(x->second->text());
    else h.u64(0).hash(node.params[e.param].content_hash());
  }
  return h.result();
}

}  // namespace

struct PlanMemo::Impl {
  // Plans whose planning read the same attributes and inputs (by name and
  // index), by the values read (trace_key).
  struct Traced {
    std::vector<std::string> attributes;
    std::vector<std::size_t> inputs;
    std::unordered_map<Hash128, std::shared_ptr<const Plan>, Hash128Hasher> plans;
  };
  // The plans of one graph (as Graph::evaluates_like) and request.
  struct ForGraph {
    std::shared_ptr<const Graph> graph;  // the first plan's
    std::vector<Traced> traces;
  };

  // The group of graphs like g in `bucket` (request_key and exposed_key), if any.
  ForGraph* like(const Hash128& bucket, const Graph& g) {
    auto [it, end] = graphs.equal_range(bucket);
    for (; it != end; ++it)
      if (it->second.graph->evaluates_like(g)) return &it->second;
    return nullptr;
  }

  // A plan that serves this evaluation, or null and, when one of a graph like
  // g is kept, that graph to plan with (its nodes outlive the caller's).
  std::pair<std::shared_ptr<const Plan>, std::shared_ptr<const Graph>> find(
      const Hash128& bucket, const Hash128& request, const Graph& g, const EvalOptions& options,
      const std::vector<Source>& inputs) {
    std::lock_guard lock(mutex);
    ForGraph* group = like(bucket, g);
    if (!group) return {};
    for (const Traced& t : group->traces)
      if (auto p = t.plans.find(trace_key(request, t.attributes, t.inputs, options, inputs)); p != t.plans.end())
        return {p->second, group->graph};
    return {nullptr, group->graph};
  }

  void keep(const Hash128& bucket, const Hash128& request, std::shared_ptr<const Plan> plan, const EvalOptions& options,
            const std::vector<Source>& inputs) {
    std::lock_guard lock(mutex);
    if (count >= kMaxPlans) return;
    ForGraph* group = like(bucket, *plan->graph);
    if (!group) group = &graphs.emplace(bucket, ForGraph{plan->graph, {}})->second;
    auto t = std::find_if(group->traces.begin(), group->traces.end(), [&](const Traced& x) {
      return x.attributes == plan->attributes_read && x.inputs == plan->inputs_read;
    });
    if (t == group->traces.end()) t = group->traces.insert(t, Traced{plan->attributes_read, plan->inputs_read, {}});
    const Hash128 key = trace_key(request, t->attributes, t->inputs, options, inputs);
    if (t->plans.emplace(key, std::move(plan)).second) ++count;  // another thread may have kept the same
  }

  mutable std::mutex mutex;
  std::unordered_multimap<Hash128, ForGraph, Hash128Hasher> graphs;  // by bucket
  std::size_t count = 0;
};

PlanMemo::PlanMemo() : impl_(std::make_unique<Impl>()) {}
PlanMemo::~PlanMemo() = default;

std::size_t PlanMemo::size() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->count;
}

const Value* EvalResult::output(std::string_view name) const {
  for (const OutputResult& o : outputs)
    if (o.name == name) return o.value.empty() ? nullptr : &o.value;
  return nullptr;
}

bool EvalResult::has_errors() const {
  return std::any_of(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& d) { return d.severity == Severity::kError; });
}

bool EvalResult::ok() const {
  return !cancelled && !has_errors() && std::all_of(outputs.begin(), outputs.end(), [](const OutputResult& o) { return !o.value.empty(); });
}

Evaluator::Evaluator(ResultCache& cache, std::string engine_salt)
    : cache_(cache), salt_(std::move(engine_salt)), salt_hash_(Hasher().str("procex-engine").str(salt_).result()) {}

namespace {
// The level of detail an evaluation shows (EvalOptions::lod). When the option
// sets it for a graph that declares the input `lod`, `bound` becomes the
// bindings with that input set to it.
int level_of_detail(const Graph& g, const Bindings& bindings, const EvalOptions& options, Bindings& bound,
                    std::vector<Diagnostic>& problems) {
  const std::optional<std::size_t> input = g.input_index("lod");
  const bool is_int = input && g.inputs()[*input].type == &value_type<std::int64_t>();
  std::int64_t level = kFullDetail;
  if (options.lod) {
    level = *options.lod;
    if (is_int) {
      bound = bindings;
      bound.insert_or_assign("lod", Value::make<std::int64_t>(level));
    }
  } else if (is_int) {
    const auto it = bindings.find("lod");
    const Value& v = it != bindings.end() ? it->second : g.inputs()[*input].default_value;
    if (v.is<std::int64_t>()) level = v.get<std::int64_t>();
  }
  if (level < 0 || level > kFullDetail) {
    problems.push_back({Severity::kError, {}, {}, "level of detail (lod) " + std::to_string(level) +
                                                      ": levels are 0 (footprint), 1 (block at the roof's mean "
                                                      "height), 2 (roof shapes) and 3 (everything)"});
    level = std::clamp<std::int64_t>(level, 0, kFullDetail);
  }
  return static_cast<int>(level);
}
}  // namespace

EvalResult Evaluator::run(const Graph& g, const Bindings& bindings, std::span<const PortRef> ports,
                          std::vector<std::string> names, const EvalOptions& options, bool compute) {
  assert(!(compute && options.assume_inputs_bound) && "EvalOptions::assume_inputs_bound is for hash_outputs only");
  const auto t0 = Clock::now();
  EvalResult result;
  Bindings bound;
  result.lod = level_of_detail(g, bindings, options, bound, result.diagnostics);
  std::vector<Source> inputs = bind_inputs(g, bound.empty() ? bindings : bound, options, result.diagnostics);
  PlanMemo::Impl* memo = options.plans && options.file_versions ? options.plans->impl_.get() : nullptr;
  Hash128 request, bucket;
  std::shared_ptr<const Plan> plan;
  std::shared_ptr<const Graph> owned;  // a memo's plan must not point into the caller's graph
  if (memo) {
    request = request_key(salt_hash_, ports, options, result.lod, inputs);
    bucket = Hasher().hash(request).hash(exposed_key(g)).result();
    std::tie(plan, owned) = memo->find(bucket, request, g, options, inputs);
    if (!plan && !owned) owned = std::make_shared<const Graph>(g);
  }
  if (!plan) {
    auto made = std::make_shared<Plan>();
    made->graph = owned;
    Planner(salt_hash_, options, result.lod, inputs, *made).plan(owned ? *owned : g, ports);
    plan = made;
    if (memo) memo->keep(bucket, request, plan, options, inputs);
  }
  result.diagnostics.insert(result.diagnostics.end(), plan->warnings.begin(), plan->warnings.end());
  Run run(cache_, options, result, *plan, std::move(inputs));
  result.stats.hash_ns = ns_since(t0);
  if (compute) run.compute();
  else run.check();
  run.report(names);
  result.stats.total_ns = ns_since(t0);
  return result;
}

namespace {
// Graph output names to the ports feeding them; unknown or unconnected ones become diagnostics.
void graph_output_ports(const Graph& g, const std::vector<std::string>& requested, std::vector<PortRef>& ports,
                        std::vector<std::string>& names, std::vector<Diagnostic>& problems) {
  std::vector<std::string> all;
  if (requested.empty())
    for (const GraphOutput& o : g.outputs()) all.push_back(o.name);
  for (const std::string& name : requested.empty() ? all : requested) {
    auto i = g.output_index(name);
    if (!i) {
      problems.push_back({Severity::kError, {}, {}, "the graph has no output named '" + name + "'"});
      continue;
    }
    auto src = g.source(PortRef{kGraphOutputs, static_cast<std::uint32_t>(*i)});
    ports.push_back(src.value_or(PortRef{kGraphInputs, 0xFFFFFFFFu}));  // resolves to "nothing connected"
    names.push_back(name);
  }
}
}  // namespace

EvalResult Evaluator::run_outputs(const Graph& g, const Bindings& bindings, const std::vector<std::string>& outputs,
                                  const EvalOptions& options, bool compute) {
  std::vector<PortRef> ports;
  std::vector<std::string> names;
  std::vector<Diagnostic> problems;
  graph_output_ports(g, outputs, ports, names, problems);
  EvalResult r = run(g, bindings, ports, std::move(names), options, compute);
  // An any-typed output (a Switch) hands on whatever its chosen input carries:
  // a graph output gets only values of its own type, as node inputs do.
  for (OutputResult& out : r.outputs) {
    const auto i = static_cast<std::uint32_t>(*g.output_index(out.name));
    const ValueType* want = g.outputs()[i].type;
    if (out.value.empty() || want->is_any() || out.value.type() == want) continue;
    const PortRef from = *g.source(PortRef{kGraphOutputs, i});
    problems.push_back({Severity::kError, {}, {}, "output '" + out.name + "' takes " + want->name() + " but " +
                                                      g.port_name(from, true) + " handed on " + out.value.type()->name() +
                                                      ": feed that node's chosen input a " + want->name()});
    out.value = {};
  }
  if (r.lod < kFullDetail)
    for (OutputResult& out : r.outputs) {
      out.hash = Hasher().hash(out.hash).str("level of detail").u64(static_cast<std::uint64_t>(r.lod)).result();
      if (!out.value.empty()) out.value = out.value.type()->at_level_of_detail(out.value, r.lod);
    }
  r.diagnostics.insert(r.diagnostics.begin(), problems.begin(), problems.end());
  return r;
}

EvalResult Evaluator::evaluate(const Graph& g, const Bindings& bindings, const std::vector<std::string>& outputs,
                               const EvalOptions& options) {
  return run_outputs(g, bindings, outputs, options, true);
}

EvalResult Evaluator::evaluate_ports(const Graph& g, const Bindings& bindings, std::span<const PortRef> ports,
                                     const EvalOptions& options) {
  std::vector<std::string> names;
  for (const PortRef& p : ports) names.push_back(g.port_name(p, true));
  return run(g, bindings, ports, std::move(names), options, true);
}

EvalResult Evaluator::hash_outputs(const Graph& g, const Bindings& bindings, const std::vector<std::string>& outputs,
                                   const EvalOptions& options) {
  return run_outputs(g, bindings, outputs, options, false);
}

}  // namespace procex
