// evaluator.h -- lazy, cached, parallel evaluation of a graph.
//
//   ResultCache cache(512 << 20);
//   Evaluator ev(cache, "procex 0.1 engine 3");          // salt: bump when results change
//   Bindings b{{"footprint", Value::make(fp)}, {"seed", Value::make<std::int64_t>(7)}};
//   EvalResult r = ev.evaluate(graph, b, {"mesh"});       // only what "mesh" needs runs
//   if (const Value* v = r.output("mesh")) use(v->get<Mesh>());
//   for (const Diagnostic& d : r.diagnostics) std::cerr << d.to_string() << "\n";
//
// How: (1) flatten groups and hash every node needed by the request, in
// dependency order: key = H(salt, type+version, params in declaration order,
// input hashes); output i's hash = H(key, i), or the input's hash for a
// pass-through (a batch plans once for many buildings and finishes only the
// keys: PlanMemo); (2) walk from the requested outputs towards the inputs,
// stopping at cache hits; (3) run the remaining nodes, independent branches
// in parallel (oneTBB), storing each success in the cache. A failed node
// poisons only its downstream; cancellation stops scheduling new nodes.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/confined_path_memo.h"
#include "base/file_version_memo.h"
#include "graph/cache.h"
#include "graph/cancel.h"
#include "graph/diagnostic.h"
#include "graph/graph.h"
#include "graph/stats.h"
#include "graph/value.h"

namespace procex {

// What a node that ran out of memory reports (std::bad_alloc's own text names
// no cause and no remedy).
inline constexpr const char* kOutOfMemory =
    "ran out of memory: this node needs more than the machine has; lower the counts and sizes it works on "
    "(a placement's rows and columns, a profile's segments, the footprint's vertices), or run fewer --jobs";

// Values for graph inputs, by name. Unbound inputs use their default.
using Bindings = std::map<std::string, Value, std::less<>>;

// Plans made for one batch, reused by its buildings (EvalOptions::plans).
// Planning a recipe (flattening its groups, evaluating its expressions,
// hashing its parameters and files) reads the graph, the request, how each
// graph input is bound and, through expressions, some attributes and input
// values; the bound values themselves only finish the keys. A plan is kept
// with what its planning read and serves every later evaluation that would
// read the same: a graph that evaluates alike (Graph::evaluates_like: a copy
// of the recipe with the same exposed values set), the same request, and the
// same values of the attributes and inputs read. Thread-safe.
class PlanMemo {
 public:
  PlanMemo();
  ~PlanMemo();
  PlanMemo(const PlanMemo&) = delete;
  PlanMemo& operator=(const PlanMemo&) = delete;
  // Plans kept. At most kMaxPlans: a batch whose features read ever new values
  // (every building's own height) plans the rest as if there were no memo.
  std::size_t size() const;
  static constexpr std::size_t kMaxPlans = 1024;

 private:
  friend class Evaluator;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct EvalOptions {
  CancelToken cancel;
  bool parallel = true;
  // Groups of groups multiply: a file of a few kilobytes can expand to
  // billions of nodes. Beyond this many flattened nodes plus group instances,
  // the remaining groups fail with an error instead.
  std::size_t max_expanded_nodes = 200000;
  // Relative file paths in parameters resolve against this folder, usually the
  // recipe's (EvalContext::folder(), NodeDecl::hash_extra). Empty: the working directory.
  std::filesystem::path folder;
  // Files named by parameters must lie inside `folder` or one of these
  // (EvalContext::file, base/confined_path.h): what `--allow-path` adds.
  std::vector<std::filesystem::path> allowed_folders;
  // Set by a batch for all its buildings: each name a parameter gives is
  // resolved and confined once (base/confined_path_memo.h). Null (the studio,
  // a single evaluation): resolved at every evaluation, so an edited symlink
  // is seen.
  std::shared_ptr<ConfinedPathMemo> resolved_paths;
  // Set by a batch too: each file's version is looked at once, and every
  // building is keyed and made from that version (base/file_version_memo.h).
  // Null: looked at whenever the graph is hashed, so an edited file is seen.
  std::shared_ptr<FileVersionMemo> file_versions;
  // Set by a batch too: plans reused across its buildings (PlanMemo). Used
  // only with file_versions, as a plan's keys hold the files' versions.
  std::shared_ptr<PlanMemo> plans;
  // The three above, fresh: what a batch sets before its first building.
  void pin_files_for_a_batch() {
    resolved_paths = std::make_shared<ConfinedPathMemo>();
    file_versions = std::make_shared<FileVersionMemo>();
    plans = std::make_shared<PlanMemo>();
  }
  // hash_outputs only: graph inputs without binding or default count as bound
  // (to a value known only by name), so checking a recipe before its inputs
  // are known reports every other problem. evaluate() asserts it is off.
  bool assume_inputs_bound = false;
  // What attr("key", default) reads in expressions: one feature's attributes
  // as text (a GeoJSON property's value). They reach a node's key through the
  // parameter values they give, so one recipe and one cache serve many features.
  std::map<std::string, std::string, std::less<>> attributes;
  // The level of detail to show (NodeDecl::detail_level, ValueType::
  // at_level_of_detail), 0 to kFullDetail. Unset: the graph input `lod` if
  // the graph declares one, else kFullDetail; set, it also binds that input,
  // so expressions read the same level.
  std::optional<int> lod;
};

struct OutputResult {
  std::string name;  // graph output name, or "12.result" for a node port request
  Value value;       // empty if it failed
  Hash128 hash;
};

struct EvalResult {
  std::vector<OutputResult> outputs;  // in request order
  std::vector<Diagnostic> diagnostics;
  EvalStats stats;
  bool cancelled = false;
  int lod = kFullDetail;  // the level of detail shown (EvalOptions::lod)

  // Null if missing or failed.
  const Value* output(std::string_view name) const;
  bool ok() const;  // every requested output present, no error diagnostics
  bool has_errors() const;
};

class Evaluator {
 public:
  Evaluator(ResultCache& cache, std::string engine_salt);

  // Requested graph outputs by name; empty = all of them. Unknown names
  // become error diagnostics.
  EvalResult evaluate(const Graph& g, const Bindings& bindings, const std::vector<std::string>& outputs = {},
                      const EvalOptions& options = {});
  // Arbitrary node outputs (an editor preview of any node).
  EvalResult evaluate_ports(const Graph& g, const Bindings& bindings, std::span<const PortRef> ports,
                            const EvalOptions& options = {});

  // Hashes of the graph outputs without evaluating anything (empty = all).
  // Problems that would stop evaluation (an unbound graph input, an
  // unconnected required input) appear as error diagnostics on the node,
  // naming its input, for every node the requested outputs need.
  EvalResult hash_outputs(const Graph& g, const Bindings& bindings, const std::vector<std::string>& outputs = {},
                          const EvalOptions& options = {});

  const std::string& engine_salt() const { return salt_; }
  ResultCache& cache() { return cache_; }

 private:
  EvalResult run(const Graph& g, const Bindings& bindings, std::span<const PortRef> ports,
                 std::vector<std::string> names, const EvalOptions& options, bool compute);
  EvalResult run_outputs(const Graph& g, const Bindings& bindings, const std::vector<std::string>& outputs,
                         const EvalOptions& options, bool compute);
  ResultCache& cache_;
  std::string salt_;
  Hash128 salt_hash_;
};

}  // namespace procex
