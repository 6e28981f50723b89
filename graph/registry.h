// registry.h -- node types by stable name, and the macro that registers one.
//
// One .cc file per node type (in an OBJECT library, so the static registrar
// survives linking):
//
//   static void declare(NodeDecl& d) { ... }
//   static void evaluate(EvalContext& ctx) { ... }
//   PROCEX_REGISTER_NODE("Offset", 1, declare, evaluate);
//
// The declare function runs lazily, on the first lookup after main() starts,
// so it may use value types registered in any other file.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "graph/eval_context.h"
#include "graph/hash.h"
#include "graph/node_decl.h"

namespace procex {

class Graph;

using DeclareFn = void (*)(NodeDecl&);
using EvaluateFn = void (*)(EvalContext&);

// A node type: its declaration and how to evaluate it. Either registered
// (evaluate set) or a group (body set: a graph whose inputs, outputs and
// exposed parameters form the declaration).
struct NodeType {
  NodeDecl decl;
  EvaluateFn evaluate = nullptr;
  DeclareFn declare = nullptr;        // registered types: run again for port-count variants
  std::shared_ptr<const Graph> body;  // groups only
  std::string source_file;            // registered types: the .cc that registered it
  Hash128 key;                        // hash of (type name, version): start of every node key

  bool is_group() const { return body != nullptr; }
  const std::string& name() const { return decl.type_name(); }
  int version() const { return decl.version(); }
};

class NodeRegistry {
 public:
  // The process-wide registry that PROCEX_REGISTER_NODE fills.
  static NodeRegistry& global();

  // Registers a type; declare runs on first lookup. Asserts on a duplicate name.
  void add(std::string type_name, int version, DeclareFn declare, EvaluateFn evaluate, std::string source_file);

  // Null when unknown.
  std::shared_ptr<const NodeType> find(std::string_view type_name) const;
  // Every registered type, sorted by name.
  std::vector<std::shared_ptr<const NodeType>> all() const;
  // The registered name closest to `name` by edit distance (case-insensitive),
  // or empty if nothing is reasonably close. For "unknown node type" messages.
  std::string closest_name(std::string_view name) const;
  // "unknown node type 'Ofset'; did you mean 'Offset'?"
  std::string unknown_type_message(std::string_view name) const;

  // Markdown docs of every type, grouped by category (for `procex nodes --markdown`).
  std::string markdown() const;

  NodeRegistry();
  ~NodeRegistry();
  NodeRegistry(const NodeRegistry&) = delete;
  NodeRegistry& operator=(const NodeRegistry&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The type a node of `type` with parameters `params` has: `type` itself when
// every port-count parameter (ParamBuilder::sets_port_count) asks for the
// counts its declaration has, else the variant declared for those counts
// (made once, then shared; same name, version, key and evaluate function).
// `params` must be complete and checked.
std::shared_ptr<const NodeType> with_port_counts(const std::shared_ptr<const NodeType>& type,
                                                 const std::vector<Value>& params);

// Levenshtein distance, case-insensitive (ASCII).
std::size_t edit_distance(std::string_view a, std::string_view b);

namespace detail {
bool register_node(const char* type_name, int version, DeclareFn declare, EvaluateFn evaluate, const char* file);
}  // namespace detail

}  // namespace procex

#define PROCEX_REGISTER_NODE_CAT2(a, b) a##b
#define PROCEX_REGISTER_NODE_CAT(a, b) PROCEX_REGISTER_NODE_CAT2(a, b)
#define PROCEX_REGISTER_NODE(type_name, version, declare, evaluate)                                   \
  [[maybe_unused]] static const bool PROCEX_REGISTER_NODE_CAT(procex_node_registered_, __LINE__) = \
      ::procex::detail::register_node(type_name, version, declare, evaluate, __FILE__)
