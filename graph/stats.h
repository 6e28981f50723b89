// stats.h -- what one evaluation did, per node: for `procex stats` and tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "graph/diagnostic.h"
#include "graph/hash.h"
#include "graph/value.h"

namespace procex {

enum class NodeOutcome {
  kCacheHit,      // result found in the cache: nothing upstream of it was visited
  kComputed,      // evaluate ran and succeeded
  kPassThrough,   // handed its input on (no compute, no cache entry)
  kFailed,        // evaluate reported an error or threw
  kInputFailed,   // not run: an input failed
  kCancelled,     // not run, or its result discarded, because of cancellation
};
const char* to_string(NodeOutcome o);

struct NodeStats {
  NodePath path;
  std::string type;
  NodeOutcome outcome = NodeOutcome::kComputed;
  Hash128 key;                 // the node's cache key
  std::uint64_t time_ns = 0;   // evaluate only (0 for hits)
  std::size_t memory = 0;      // bytes of the node's outputs
  // The parameter values it ran with where they are not its own (expressions
  // evaluated, a group's exposed values applied), in declaration order; empty
  // when they are its own. An editor shows an expression's value from here.
  std::vector<Value> params;
};

struct EvalStats {
  std::vector<NodeStats> nodes;  // every node visited, ordered by path
  std::uint64_t total_ns = 0;    // wall time of the whole evaluation
  std::uint64_t hash_ns = 0;     // of which: planning and hashing

  std::size_t count(NodeOutcome o) const;
  std::size_t computed() const { return count(NodeOutcome::kComputed); }
  const NodeStats* find(const NodePath& path) const;
  // A table: path, type, outcome, time, memory; then totals.
  void print(std::ostream& out) const;
};

}  // namespace procex
