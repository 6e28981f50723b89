// Bytes set aside while a long run goes on, to be copied into an output when
// it ends without coming back into memory (a batch's report entries, a
// streamed .glb's chunks): an unnamed temporary file (O_TMPFILE) in the
// folder given, beside the output it is for (folder_beside): on the disk that
// is to hold the output, not filling /tmp, and gone with the process whatever
// happens, SIGINT, SIGTERM and SIGKILL included. On a file system without
// O_TMPFILE it is a file named procex-spool-XXXXXX, unlinked as it is made.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace procex {

class SpoolFile {
 public:
  explicit SpoolFile(const std::string& folder);  // in `folder`; throws IoError naming it
  SpoolFile(const SpoolFile&) = delete;
  SpoolFile& operator=(const SpoolFile&) = delete;
  ~SpoolFile();

  // Throws IoError (the temporary folder is full) naming the folder.
  void append(std::string_view bytes);
  std::uint64_t size() const { return written_ + buffer_.size(); }
  // Hands every byte appended so far to each, in order, a bounded chunk at a
  // time. Throws IoError if the file cannot be read back.
  void read(const std::function<void(std::string_view)>& each) const;
  // The `length` bytes appended from byte `offset` on (a record set aside and
  // wanted back alone). Throws IoError as read does, or if they were never appended.
  std::string read_at(std::uint64_t offset, std::size_t length) const;

 private:
  void flush();
  // Fills out with the file's bytes from `at` (all within written_).
  void pread_all(std::uint64_t at, std::span<char> out) const;
  std::string folder_;
  int fd_ = -1;
  std::string buffer_;  // appended, not yet in the file
  std::uint64_t written_ = 0;
};

// The folder a file is (to be) written in, for its spools: "." for a bare name.
std::string folder_beside(const std::filesystem::path& file);

}  // namespace procex
