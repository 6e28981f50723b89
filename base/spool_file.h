// Bytes set aside while a long run goes on, to be copied into an output when
// it ends without coming back into memory (a batch's report entries, a
// streamed .glb's chunks): an unnamed temporary file in TMPDIR (else /tmp),
// or in a folder given (beside a batch's output), so it goes away with the
// process whatever happens, SIGINT, SIGTERM and SIGKILL included.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

namespace procex {

class SpoolFile {
 public:
  SpoolFile();  // throws IoError naming the temporary folder
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
  SpoolFile(std::string folder, bool from_tmpdir);
  std::string folder_;
  bool from_tmpdir_;  // the folder is TMPDIR's (messages say how to name another)
  int fd_ = -1;
  std::string buffer_;  // appended, not yet in the file
  std::uint64_t written_ = 0;
};

}  // namespace procex
