// Reading a whole input file that someone else may have made: a path given on
// the command line or named in a shared recipe can be a directory, a FIFO
// that never ends, a device or a file too large to hold. One reader for every
// input, so each refuses those the same way and names the system's reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <span>
#include <string>

#include "base/io_error.h"

namespace procex {

// Largest footprint, shape, report or mesh file read (a city's footprints fit
// many times over); parsing takes several times the file's size in memory.
inline constexpr std::size_t kMaxDataFileBytes = std::size_t{1} << 30;

// The file's bytes. Throws IoError naming the path and why it cannot be read
// (no such file, permission denied, is a directory, not a regular file, more
// than max_bytes), never blocking on a FIFO.
std::string read_file(const std::filesystem::path& path, std::size_t max_bytes);

// The same file, checked the same way, as a stream read a chunk at a time:
// for a reader that takes what it needs as it goes instead of the file whole.
// A read that fails later throws std::ios_base::failure from the stream's
// buffer (readers that call it directly, as nlohmann's parser does, see it).
std::unique_ptr<std::istream> open_file_stream(const std::filesystem::path& path, std::size_t max_bytes);

// The same file, checked the same way, read by ranges where the caller wants
// them (a .glb's JSON elements and buffer views), never whole.
class RangedFile {
 public:
  RangedFile(const std::filesystem::path& path, std::size_t max_bytes);
  RangedFile(const RangedFile&) = delete;
  RangedFile& operator=(const RangedFile&) = delete;
  ~RangedFile();
  std::uint64_t size() const { return size_; }
  // Fills out with the bytes from `offset` on. Throws IoError naming the file
  // if they are not all there (it shrank since it was opened) or cannot be read.
  void read_at(std::uint64_t offset, std::span<char> out) const;

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

}  // namespace procex
