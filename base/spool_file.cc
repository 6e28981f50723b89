#include "base/spool_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "base/io_error.h"

namespace procex {
namespace {

// Large enough that appends and copies are few system calls, small enough
// that a spool's memory does not matter beside what it saves.
constexpr std::size_t kChunk = std::size_t{1} << 20;

}  // namespace

std::string folder_beside(const std::filesystem::path& file) {
  const std::filesystem::path folder = file.parent_path();
  return folder.empty() ? "." : folder.string();
}

SpoolFile::SpoolFile(const std::string& folder) : folder_(folder) {
  fd_ = ::open(folder_.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd_ < 0) {  // a file system without O_TMPFILE: a named file, unlinked at once
    std::string name = folder_ + "/procex-spool-XXXXXX";
    fd_ = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd_ >= 0) ::unlink(name.c_str());
  }
  if (fd_ < 0)
    throw IoError("cannot make a temporary file in '" + folder_ + "': " + std::strerror(errno), folder_);
  buffer_.reserve(kChunk);
}

SpoolFile::~SpoolFile() {
  if (fd_ >= 0) ::close(fd_);
}

void SpoolFile::append(std::string_view bytes) {
  if (buffer_.size() + bytes.size() > kChunk) flush();
  if (bytes.size() >= kChunk) {
    buffer_ = bytes;
    flush();
    buffer_.shrink_to_fit(), buffer_.reserve(kChunk);
  } else {
    buffer_ += bytes;
  }
}

void SpoolFile::flush() {
  for (std::size_t done = 0; done < buffer_.size();) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw IoError("cannot write a temporary file in '" + folder_ + "': " + std::strerror(n < 0 ? errno : ENOSPC) +
                        " (is the disk full?)",
                    folder_);
    done += static_cast<std::size_t>(n);
  }
  written_ += buffer_.size();
  buffer_.clear();
}

void SpoolFile::pread_all(std::uint64_t at, std::span<char> out) const {
  for (std::size_t done = 0; done < out.size();) {
    const ssize_t n = ::pread(fd_, out.data() + done, out.size() - done, static_cast<off_t>(at + done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw IoError("cannot read back a temporary file in '" + folder_ + "': " + std::strerror(n < 0 ? errno : EIO),
                    folder_);
    done += static_cast<std::size_t>(n);
  }
}

void SpoolFile::read(const std::function<void(std::string_view)>& each) const {
  std::vector<char> chunk(written_ > 0 ? kChunk : 0);
  for (std::uint64_t at = 0; at < written_;) {
    const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, written_ - at));
    pread_all(at, std::span(chunk.data(), want));
    each(std::string_view(chunk.data(), want));
    at += want;
  }
  if (!buffer_.empty()) each(buffer_);
}

std::string SpoolFile::read_at(std::uint64_t offset, std::size_t length) const {
  if (offset > size() || length > size() - offset)
    throw IoError("cannot read back bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) +
                      " of a temporary file of " + std::to_string(size()),
                  folder_);
  std::string out(length, '\0');
  const std::size_t from_file = static_cast<std::size_t>(std::min<std::uint64_t>(length, written_ > offset ? written_ - offset : 0));
  pread_all(offset, std::span(out.data(), from_file));
  // The rest is still in the buffer, which starts at written_.
  if (from_file < length)
    std::copy_n(buffer_.data() + (offset + from_file - written_), length - from_file, out.data() + from_file);
  return out;
}

}  // namespace procex
