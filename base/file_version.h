// Which version of a file a recipe names is on disk, for the caches keyed by
// it (a node's key: graph hash_file_stamp; a texture or mesh read once and
// shared): its size, modification time and a hash of its bytes. Size and
// time alone miss an edit that keeps the size within one tick of the file
// system's clock (a few milliseconds on Linux: an editor saving twice, a test
// rewriting a file), so the bytes are hashed too, once per version.
#pragma once

#include <cstdint>
#include <filesystem>

namespace procex {

struct FileVersion {
  std::uintmax_t size = static_cast<std::uintmax_t>(-1);  // -1: not there
  std::int64_t time = 0;                                   // modification time, the clock's ticks
  std::uint64_t content = 0;                               // hash of the bytes; 0 for no readable regular file
  bool operator==(const FileVersion&) const = default;
  auto operator<=>(const FileVersion&) const = default;
};

// Reads the file only when this version's bytes were not hashed yet, or were
// hashed within a moment of its modification time (it may have been written
// again within the same tick at the same size: a "racy" version, as git
// calls it). Never throws: a missing or unreadable file has a version of its
// own, and reading it for use says why. Thread-safe.
FileVersion file_version(const std::filesystem::path& file);

}  // namespace procex
