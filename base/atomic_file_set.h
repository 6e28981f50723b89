// Files that must change together or not at all: a mesh and its report, an
// .obj and its .mtl. Each is written to a temporary file beside its target and
// synced to disk; commit() renames them all and syncs their folders. What is
// not committed (an error, an exception, SIGINT or SIGTERM while writing) is
// removed, so a failed or interrupted run leaves the old files and no
// temporaries. write_file_atomically (base/atomic_write.h) is a set of one.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/io_error.h"
#include "base/spool_file.h"

namespace procex {

// A piece of a file being written: bytes in memory, or all a spool holds
// (copied from its file, never read into memory whole).
struct FilePiece {
  std::string_view bytes;
  const SpoolFile* spool = nullptr;
};

class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;
  ~AtomicFileSet();  // removes every temporary file not committed

  // Writes the temporary file for path; adding a path again replaces what was
  // written for it (a report staged before a long write, to know it can be
  // written, then with its final numbers). Throws IoError naming path and
  // the system's reason (nothing of this set is then left behind by the
  // destructor).
  void add(const std::filesystem::path& path, std::span<const std::string_view> pieces);
  void add(const std::filesystem::path& path, std::span<const FilePiece> pieces);
  void add(const std::filesystem::path& path, std::string_view contents);
  // Renames every file into place, in the order added. Throws IoError if a
  // rename fails (the files renamed before it stay).
  void commit();

 private:
  struct Staged {
    std::filesystem::path target, temp;
  };
  std::vector<Staged> staged_;
};

}  // namespace procex
