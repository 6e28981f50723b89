#include "graph/evaluator.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <new>
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
  Value value;               // kValue
  Hash128 hash;              // kNode, kValue
  std::string why;           // kMissing: for the consumer's error
};

// kHashed: needed by a hash-only request, nothing wrong found.
enum class State { kPending, kHashed, kHit, kCompute, kDone, kFailed, kInputFailed, kCancelled };

struct PlanNode {
  NodePath path;
  const Node* node = nullptr;
  std::vector<Value> overridden;  // exposed parameters of enclosing groups applied; empty: none
  std::vector<Source> inputs;
  Hash128 key;
  std::vector<Hash128> out_hash;
  std::vector<std::optional<std::uint32_t>> passes;  // output i hands on input *passes[i]
  std::string static_error;                           // found while planning: never evaluated
  // Filled by evaluation:
  State state = State::kPending;
  std::vector<Value> outputs;
  std::vector<std::string> warnings;
  std::vector<std::size_t> dependents;
  std::atomic<int> pending{0};
  std::uint64_t time_ns = 0;

  const std::vector<Value>& params() const { return overridden.empty() ? node->params : overridden; }
  const NodeDecl& decl() const { return node->decl(); }
};

// One graph being flattened: the recipe itself, or the body of one group instance.
struct Frame {
  const Graph* graph = nullptr;
  NodePath prefix;
  std::vector<Source> inputs;                                     // group bodies: what feeds each body input
  std::unordered_map<NodeId, std::vector<std::pair<std::uint32_t, Value>>> overrides;  // node -> (param, value)
  std::unordered_map<NodeId, std::size_t> plan_index;             // regular nodes
  std::unordered_map<NodeId, std::vector<Source>> group_outputs;  // group instances
};

class Run {
 public:
  Run(ResultCache& cache, const Hash128& salt, const EvalOptions& options, int level, EvalResult& result)
      : cache_(cache), salt_(salt), options_(options), level_(level), result_(result) {}

  // Phase 1: flattens and hashes what `ports` (outputs of the top graph) need.
  std::vector<Source> plan(const Graph& g, const Bindings& bindings, std::span<const PortRef> ports) {
    Frame top;
    top.graph = &g;
    for (const auto& [name, v] : bindings)
      if (!g.input_index(name)) warn_graph("no graph input named '" + name + "'; the binding is ignored");
    for (const GraphInput& in : g.inputs()) top.inputs.push_back(bind(in, bindings));
    std::vector<NodeId> starts;
    for (const PortRef& p : ports)
      if (p.node != kGraphInputs) starts.push_back(p.node);
    flatten(top, starts, 0);
    std::vector<Source> out;
    for (const PortRef& p : ports) out.push_back(resolve(top, p));
    return out;
  }

  // Hash-only runs: marks the nodes the request needs, so that those whose
  // inputs are missing (unbound, unconnected) report it as compute() would.
  void check(const std::vector<Source>& wanted) { walk(wanted, false); }

  // Phase 2 and 3: finds what is not cached and computes it.
  void compute(const std::vector<Source>& wanted) {
    const std::vector<std::size_t> to_run = walk(wanted, true);
    std::vector<std::size_t> ready;
    for (std::size_t i : to_run) {
      PlanNode& n = *plan_[i];
      std::vector<std::size_t> deps;
      for (const Source& s : n.inputs)
        if (s.kind == Source::kNode && plan_[s.node]->state == State::kCompute) deps.push_back(s.node);
      std::sort(deps.begin(), deps.end());
      deps.erase(std::unique(deps.begin(), deps.end()), deps.end());
      n.pending.store(static_cast<int>(deps.size()), std::memory_order_relaxed);
      for (std::size_t d : deps) plan_[d]->dependents.push_back(i);
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
        for (std::size_t d : plan_[i]->dependents)
          if (plan_[d]->pending.fetch_sub(1) == 1) queue.push_back(d);
      }
    }
  }

  // Values, statistics and diagnostics into the result.
  void report(const std::vector<Source>& wanted, const std::vector<std::string>& names) {
    for (std::size_t k = 0; k < wanted.size(); ++k) {
      const Source& s = wanted[k];
      OutputResult r{names[k], {}, s.hash};
      if (s.kind == Source::kValue) r.value = s.value;
      if (s.kind == Source::kNode) {
        const PlanNode& n = *plan_[s.node];
        if (n.state == State::kHit || n.state == State::kDone) r.value = n.outputs[s.port];
      }
      if (s.kind == Source::kMissing || s.kind == Source::kUnconnected)
        result_.diagnostics.push_back({Severity::kError, {}, {}, "output '" + names[k] + "': " +
                                                                   (s.why.empty() ? "nothing is connected" : s.why)});
      result_.outputs.push_back(std::move(r));
    }
    std::vector<std::size_t> order(plan_.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [this](std::size_t a, std::size_t b) { return plan_[a]->path < plan_[b]->path; });
    for (std::size_t i : order) report_node(*plan_[i]);
    for (const auto& pt : pass_through_stats_) result_.stats.nodes.push_back(pt);
    std::sort(result_.stats.nodes.begin(), result_.stats.nodes.end(),
              [](const NodeStats& a, const NodeStats& b) { return a.path < b.path; });
    result_.cancelled = options_.cancel.cancelled();
  }

 private:
  // From the requested outputs towards the inputs: nodes with a static error
  // fail; with `use_cache`, cache hits stop the walk and the nodes to compute
  // are returned; without, every needed node is only marked as hashed.
  std::vector<std::size_t> walk(const std::vector<Source>& wanted, bool use_cache) {
    std::vector<std::size_t> stack;
    for (const Source& s : wanted)
      if (s.kind == Source::kNode) stack.push_back(s.node);
    std::vector<std::size_t> to_run;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      PlanNode& n = *plan_[i];
      if (n.state != State::kPending) continue;
      if (!n.static_error.empty()) {
        n.state = State::kFailed;
        continue;
      }
      if (!use_cache) {
        n.state = State::kHashed;
      } else if (CachedOutputs hit = cache_.find(n.key)) {
        n.state = State::kHit;
        const std::size_t count = n.decl().outputs().size();
        n.outputs.assign(hit->begin(), hit->begin() + static_cast<std::ptrdiff_t>(count));
        if (hit->size() > count) n.warnings = hit->back().get<std::vector<std::string>>();
        continue;
      } else {
        n.state = State::kCompute;
        to_run.push_back(i);
      }
      for (const Source& s : n.inputs)
        if (s.kind == Source::kNode) stack.push_back(s.node);
    }
    return to_run;
  }

  Source bind(const GraphInput& in, const Bindings& bindings) {
    Source s;
    auto it = bindings.find(in.name);
    const Value* v = it != bindings.end() ? &it->second : (in.default_value.empty() ? nullptr : &in.default_value);
    if ((!v || v->empty()) && options_.assume_inputs_bound) {
      s.kind = Source::kValue;  // no value: only hash_outputs may use this option
      s.hash = Hasher().str("unbound graph input").str(in.name).result();
    } else if (!v || v->empty()) {
      s.kind = Source::kMissing;
      s.why = "graph input '" + in.name + "' is not bound and has no default";
    } else if (!in.type->is_any() && v->type() != in.type) {
      s.kind = Source::kMissing;
      s.why = "graph input '" + in.name + "' takes " + in.type->name() + " but was bound to " + v->type()->name();
      warn_graph(s.why);
    } else {
      s.kind = Source::kValue;
      s.value = *v;
      s.hash = v->content_hash();
    }
    return s;
  }

  void warn_graph(std::string message) { result_.diagnostics.push_back({Severity::kWarning, {}, {}, std::move(message)}); }

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
    const PlanNode& n = *plan_[it->second];
    if (p.port >= n.out_hash.size()) return Source{};
    if (n.passes[p.port]) return n.inputs[*n.passes[p.port]];
    Source s;
    s.kind = Source::kNode;
    s.node = it->second;
    s.port = p.port;
    s.hash = n.out_hash[p.port];
    return s;
  }

  Source resolve_input(const Frame& f, PortRef to) const {
    auto it = f.graph->links().find(to);
    if (it == f.graph->links().end()) return Source{};
    return resolve(f, it->second);
  }

  // Visits the nodes `starts` need in dependency order (iteratively: chains
  // may be long), creating plan nodes and hashing them.
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
                                      std::vector<std::string>* warnings = nullptr) const {
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
                    std::vector<std::string>* warnings) const {
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
  ExprValue name_value(const Frame& f, std::string_view name, std::size_t depth, std::vector<std::string>* warnings) const {
    std::string q = "'";  // appended, not added: GCC 12's -Wrestrict misreads '"x" + std::string(...)' here
    q.append(name).append("'");
    if (auto i = f.graph->input_index(name)) {
      const Source& s = *i < f.inputs.size() ? f.inputs[*i] : Source{};
      if (s.kind == Source::kValue && s.value.empty()) {  // assume_inputs_bound: any value of the type will do
        const ExprType t = expression_type(*f.graph->inputs()[*i].type).value_or(ExprType::kNumber);
        return t == ExprType::kNumber ? ExprValue(0.0) : t == ExprType::kBool ? ExprValue(false) : ExprValue(std::string());
      }
      if (s.kind == Source::kValue && expression_type(*s.value.type())) return to_expr_value(s.value);
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
  std::optional<std::uint32_t> passed_input(const Frame& f, NodeId id) const {
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
    for (std::string& w : param_warnings) result_.diagnostics.push_back({Severity::kWarning, path, node->type->name(), std::move(w)});
    if (node->type->is_group()) {
      emit_group(f, *node, std::move(path), overridden.empty() ? node->params : overridden, param_error, depth);
      return;
    }
    auto pn = std::make_unique<PlanNode>();
    PlanNode& n = *pn;
    n.path = std::move(path);
    n.node = node;
    n.overridden = std::move(overridden);
    n.static_error = std::move(param_error);
    Hasher h;
    h.hash(salt_).hash(node->type->key);
    for (const Value& v : n.params()) v.hash(h);
    for (const auto& [p, e] : node->expressions) h.u64(p).str(e->text());
    if (decl.hash_extra()) decl.hash_extra()(n.params(), options_.folder, options_.file_versions.get(), h);
    n.inputs.reserve(decl.inputs().size());
    const std::optional<std::uint32_t> only = passed_input(f, id);
    for (std::uint32_t i = 0; i < decl.inputs().size(); ++i) {
      if (only && i != *only) {  // not planned (flatten): never read, since every output passes *only on
        n.inputs.emplace_back();
        h.u64(0x9e3779b97f4a7c15ull + Source::kUnconnected);
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
      if (s.kind == Source::kNode || s.kind == Source::kValue) h.hash(s.hash);
      else h.u64(0x9e3779b97f4a7c15ull + s.kind);
      n.inputs.push_back(std::move(s));
    }
    if (only && n.static_error.empty() && n.inputs[*only].kind != Source::kNode && n.inputs[*only].kind != Source::kValue)
      n.static_error = "input '" + decl.inputs()[*only].name + "' has no value";  // and the others were not planned
    n.key = h.result();
    const std::size_t outs = decl.outputs().size();
    n.out_hash.resize(outs);
    n.passes.resize(outs);
    for (std::uint32_t o = 0; o < outs; ++o) {
      const std::optional<std::size_t> pass = forwarded(decl, n.params(), o);
      if (pass && *pass < n.inputs.size() &&
          (n.inputs[*pass].kind == Source::kNode || n.inputs[*pass].kind == Source::kValue)) {
        n.passes[o] = static_cast<std::uint32_t>(*pass);
        n.out_hash[o] = n.inputs[*pass].hash;
      } else {
        n.out_hash[o] = Hasher().hash(n.key).u64(o).result();
      }
    }
    if (outs > 0 && std::all_of(n.passes.begin(), n.passes.end(), [](const auto& p) { return p.has_value(); })) {
      // Never evaluated: consumers read straight from its inputs.
      pass_through_stats_.push_back(NodeStats{n.path, node->type->name(), NodeOutcome::kPassThrough, n.key, 0, 0, n.overridden});
    }
    f.plan_index.emplace(id, plan_.size());
    plan_.push_back(std::move(pn));
  }

  void emit_group(Frame& f, const Node& node, NodePath path, const std::vector<Value>& params,
                  const std::string& param_error, std::size_t depth) {
    const Graph& body = *node.type->body;
    std::vector<Source>& outs = f.group_outputs[node.id];
    const bool too_deep = depth + 1 > kMaxGroupDepth;
    if (!param_error.empty() || too_deep || ++expanded_ + plan_.size() > options_.max_expanded_nodes) {
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

  void run_parallel(std::size_t i, tbb::task_group& tg) {
    evaluate_node(i);
    for (std::size_t d : plan_[i]->dependents)
      if (plan_[d]->pending.fetch_sub(1, std::memory_order_acq_rel) == 1) tg.run([this, d, &tg] { run_parallel(d, tg); });
  }

  void evaluate_node(std::size_t i) {
    PlanNode& n = *plan_[i];
    const NodeDecl& decl = n.decl();
    std::vector<Value> inputs(n.inputs.size());
    for (std::size_t k = 0; k < n.inputs.size(); ++k) {
      const Source& s = n.inputs[k];
      if (s.kind == Source::kValue) inputs[k] = s.value;
      if (s.kind != Source::kNode) continue;
      const PlanNode& up = *plan_[s.node];
      if (up.state == State::kCancelled) {
        n.state = State::kCancelled;
        return;
      }
      if (up.state != State::kHit && up.state != State::kDone) {
        n.state = State::kInputFailed;
        n.static_error = "input failed: '" + decl.inputs()[k].name + "' comes from node " + to_string(up.path) +
                         " (" + up.node->type->name() + "), which has no result";
        return;
      }
      inputs[k] = up.outputs[s.port];
      const ValueType* want = decl.inputs()[k].type;
      if (!want->is_any() && inputs[k].type() != want) {
        n.state = State::kFailed;
        n.static_error = "input '" + decl.inputs()[k].name + "' takes " + want->name() + " but received " +
                         inputs[k].type()->name();
        return;
      }
    }
    if (options_.cancel.cancelled()) {
      n.state = State::kCancelled;
      return;
    }
    EvalContext ctx(decl, n.params(), inputs, options_.cancel, options_.folder, options_.allowed_folders,
                    options_.resolved_paths.get(), options_.file_versions.get());
    const auto t0 = Clock::now();
    try {
      n.node->type->evaluate(ctx);
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
      n.static_error = error;
      return;
    }
    n.outputs = std::move(ctx.outputs());
    n.state = State::kDone;
    std::vector<Value> entry = n.outputs;
    if (!warnings.empty()) entry.push_back(Value::make(std::move(warnings)));
    cache_.insert(n.key, std::move(entry));
  }

  void report_node(const PlanNode& n) {
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
    const std::string& type = n.node->type->name();
    result_.stats.nodes.push_back(NodeStats{n.path, type, outcome, n.key, n.time_ns, memory, n.overridden});
    for (const std::string& w : n.warnings) result_.diagnostics.push_back({Severity::kWarning, n.path, type, w});
    if (outcome == NodeOutcome::kFailed || outcome == NodeOutcome::kInputFailed)
      result_.diagnostics.push_back({Severity::kError, n.path, type, n.static_error});
  }

  ResultCache& cache_;
  Hash128 salt_;
  const EvalOptions& options_;
  const int level_;  // of detail
  EvalResult& result_;
  std::vector<std::unique_ptr<PlanNode>> plan_;
  std::vector<NodeStats> pass_through_stats_;
  std::size_t expanded_ = 0;  // group instances flattened so far
};

}  // namespace

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
  Run run(cache_, salt_hash_, options, result.lod, result);
  std::vector<Source> wanted = run.plan(g, bound.empty() ? bindings : bound, ports);
  result.stats.hash_ns = ns_since(t0);
  if (compute) run.compute(wanted);
  else run.check(wanted);
  run.report(wanted, names);
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
