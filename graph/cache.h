// cache.h -- node results keyed by their 128-bit hash, bounded in bytes, LRU.
//
// Thread-safe. One entry per evaluated node: all its outputs. Errors are never
// stored. Values are shared, so a result handed out stays valid after eviction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "graph/hash.h"
#include "graph/value.h"

namespace procex {

using CachedOutputs = std::shared_ptr<const std::vector<Value>>;

struct CacheCounters {
  std::uint64_t hits = 0, misses = 0, insertions = 0, evictions = 0;
  std::size_t entries = 0;
  std::size_t bytes = 0;     // values plus per-entry bookkeeping
  std::size_t capacity = 0;
};

class ResultCache {
 public:
  static constexpr std::size_t kDefaultCapacity = std::size_t{1} << 30;  // 1 GiB
  // Bytes charged per entry for the key, LRU list and index nodes, the shared
  // vector and the values' control blocks: measured by bench/graph_bench.cc
  // (heap growth per cached one-double result: ~226 bytes).
  static constexpr std::size_t kEntryOverhead = 192;

  explicit ResultCache(std::size_t capacity_bytes = kDefaultCapacity);
  ~ResultCache();
  ResultCache(const ResultCache&) = delete;
  ResultCache& operator=(const ResultCache&) = delete;

  // Null on a miss; a hit becomes the most recently used entry.
  CachedOutputs find(const Hash128& key);
  // Stores (or refreshes) an entry, then evicts least recently used entries
  // until the total fits. A result larger than the whole capacity is not stored.
  void insert(const Hash128& key, std::vector<Value> outputs);
  bool contains(const Hash128& key) const;

  void set_capacity(std::size_t bytes);
  void clear();
  CacheCounters counters() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace procex
