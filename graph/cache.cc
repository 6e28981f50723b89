#include "graph/cache.h"

#include <list>
#include <mutex>
#include <unordered_map>

namespace procex {

namespace {
struct Entry {
  Hash128 key;
  CachedOutputs outputs;
  std::size_t bytes;
};
}  // namespace

struct ResultCache::Impl {
  mutable std::mutex mutex;
  std::list<Entry> lru;  // front: most recently used
  std::unordered_map<Hash128, std::list<Entry>::iterator, Hash128Hasher> index;
  std::size_t bytes = 0;
  std::size_t capacity;
  CacheCounters counters;

  void evict_to(std::size_t limit) {
    while (bytes > limit && !lru.empty()) {
      bytes -= lru.back().bytes;
      index.erase(lru.back().key);
      lru.pop_back();
      ++counters.evictions;
    }
  }
};

ResultCache::ResultCache(std::size_t capacity_bytes) : impl_(std::make_unique<Impl>()) { impl_->capacity = capacity_bytes; }
ResultCache::~ResultCache() = default;

CachedOutputs ResultCache::find(const Hash128& key) {
  std::lock_guard lock(impl_->mutex);
  auto it = impl_->index.find(key);
  if (it == impl_->index.end()) {
    ++impl_->counters.misses;
    return nullptr;
  }
  ++impl_->counters.hits;
  impl_->lru.splice(impl_->lru.begin(), impl_->lru, it->second);
  return it->second->outputs;
}

bool ResultCache::contains(const Hash128& key) const {
  std::lock_guard lock(impl_->mutex);
  return impl_->index.count(key) != 0;
}

void ResultCache::insert(const Hash128& key, std::vector<Value> outputs) {
  std::size_t bytes = kEntryOverhead + outputs.capacity() * sizeof(Value);
  for (const Value& v : outputs) bytes += v.memory_size();
  auto shared = std::make_shared<const std::vector<Value>>(std::move(outputs));
  std::lock_guard lock(impl_->mutex);
  if (auto it = impl_->index.find(key); it != impl_->index.end()) {
    impl_->bytes -= it->second->bytes;
    impl_->lru.erase(it->second);
    impl_->index.erase(it);
  }
  if (bytes > impl_->capacity) return;
  impl_->lru.push_front(Entry{key, std::move(shared), bytes});
  impl_->index.emplace(key, impl_->lru.begin());
  impl_->bytes += bytes;
  ++impl_->counters.insertions;
  impl_->evict_to(impl_->capacity);
}

void ResultCache::set_capacity(std::size_t bytes) {
  std::lock_guard lock(impl_->mutex);
  impl_->capacity = bytes;
  impl_->evict_to(bytes);
}

void ResultCache::clear() {
  std::lock_guard lock(impl_->mutex);
  impl_->lru.clear();
  impl_->index.clear();
  impl_->bytes = 0;
}

CacheCounters ResultCache::counters() const {
  std::lock_guard lock(impl_->mutex);
  CacheCounters c = impl_->counters;
  c.entries = impl_->index.size();
  c.bytes = impl_->bytes;
  c.capacity = impl_->capacity;
  return c;
}

}  // namespace procex
