// What was read from a file, kept for the version it was read at: the meshes
// and textures a batch's buildings share, read once. A file's new version
// replaces its old one, so an edited file leaves nothing behind, and a batch,
// which asks for one version of each file all along (FileVersionMemo), never
// reads a file twice, however many files its recipe names. (A cache cleared
// when full read a file again under the version the batch had pinned, though
// the disk may hold another by then.) It holds one entry a file ever read.
#pragma once

#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>

namespace procex {

template <class Version, class Value>
class FileReadCache {
 public:
  // The value read for `file` at `version`, or read(), kept for it. Reads
  // under the lock: workers asking at once read a file once. Thread-safe.
  template <class Read>
  Value get(const std::string& file, const Version& version, Read read) {
    std::lock_guard lock(mutex_);
    if (const auto it = entries_.find(file); it != entries_.end() && it->second.first == version) return it->second.second;
    Value value = read();
    entries_.insert_or_assign(file, std::pair<Version, Value>(version, value));
    return value;
  }

 private:
  std::mutex mutex_;
  std::unordered_map<std::string, std::pair<Version, Value>> entries_;
};

}  // namespace procex
