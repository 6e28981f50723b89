#include "graph/stats.h"

#include <cstdio>
#include <ostream>

namespace procex {

const char* to_string(NodeOutcome o) {
  switch (o) {
    case NodeOutcome::kCacheHit: return "cache hit";
    case NodeOutcome::kComputed: return "computed";
    case NodeOutcome::kPassThrough: return "pass-through";
    case NodeOutcome::kFailed: return "FAILED";
    case NodeOutcome::kInputFailed: return "input failed";
    case NodeOutcome::kCancelled: return "cancelled";
  }
  return "?";
}

std::size_t EvalStats::count(NodeOutcome o) const {
  std::size_t n = 0;
  for (const NodeStats& s : nodes) n += s.outcome == o;
  return n;
}

const NodeStats* EvalStats::find(const NodePath& path) const {
  for (const NodeStats& s : nodes)
    if (s.path == path) return &s;
  return nullptr;
}

namespace {
std::string human_bytes(std::size_t b) {
  char buf[32];
  if (b < 10 * 1024) std::snprintf(buf, sizeof buf, "%zu B", b);
  else if (b < 10 * 1024 * 1024) std::snprintf(buf, sizeof buf, "%.1f KiB", static_cast<double>(b) / 1024);
  else std::snprintf(buf, sizeof buf, "%.1f MiB", static_cast<double>(b) / (1024 * 1024));
  return buf;
}
}  // namespace

void EvalStats::print(std::ostream& out) const {
  char line[256];
  std::snprintf(line, sizeof line, "%-12s %-24s %-13s %12s %12s\n", "node", "type", "outcome", "time (ms)", "memory");
  out << line;
  std::uint64_t compute_ns = 0;
  std::size_t memory = 0;
  for (const NodeStats& s : nodes) {
    std::snprintf(line, sizeof line, "%-12s %-24.24s %-13s %12.3f %12s\n", to_string(s.path).c_str(), s.type.c_str(),
                  to_string(s.outcome), static_cast<double>(s.time_ns) / 1e6, human_bytes(s.memory).c_str());
    out << line;
    compute_ns += s.time_ns;
    memory += s.memory;
  }
  std::snprintf(line, sizeof line,
                "%zu nodes: %zu computed, %zu cache hits, %zu pass-through, %zu failed, %zu input failed, %zu "
                "cancelled\n",
                nodes.size(), count(NodeOutcome::kComputed), count(NodeOutcome::kCacheHit),
                count(NodeOutcome::kPassThrough), count(NodeOutcome::kFailed), count(NodeOutcome::kInputFailed),
                count(NodeOutcome::kCancelled));
  out << line;
  std::snprintf(line, sizeof line, "wall %.3f ms (planning and hashing %.3f ms), node compute %.3f ms, outputs %s\n",
                static_cast<double>(total_ns) / 1e6, static_cast<double>(hash_ns) / 1e6,
                static_cast<double>(compute_ns) / 1e6, human_bytes(memory).c_str());
  out << line;
}

}  // namespace procex
