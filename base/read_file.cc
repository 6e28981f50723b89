#include "base/read_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <streambuf>
#include <utility>
#include <vector>

namespace procex {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
  throw IoError("cannot read '" + path.string() + "': " + why, path.string());
}

// Closes the descriptor on every way out.
struct Fd {
  int fd;
  explicit Fd(int d) : fd(d) {}
  Fd(Fd&& o) noexcept : fd(std::exchange(o.fd, -1)) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// Opens path for reading if it is a regular file of at most max_bytes; its size.
std::size_t open_checked(const std::filesystem::path& path, std::size_t max_bytes, Fd& file) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  file.fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (file.fd < 0) fail(path, std::strerror(errno));
  struct stat st {};
  if (::fstat(file.fd, &st) != 0) fail(path, std::strerror(errno));
  if (S_ISDIR(st.st_mode)) fail(path, "it is a folder, not a file");
  if (!S_ISREG(st.st_mode)) fail(path, "it is not a regular file (a device, FIFO or socket)");
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size > max_bytes)
    fail(path, "it is " + std::to_string(size) + " bytes; the limit for this kind of file is " + std::to_string(max_bytes));
  return size;
}

// A file's bytes a chunk at a time, through the descriptor it owns.
class FileBuffer : public std::streambuf {
 public:
  explicit FileBuffer(Fd file) : file_(std::move(file)), chunk_(std::size_t{1} << 20) {}

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    for (;;) {
      const ssize_t n = ::read(file_.fd, chunk_.data(), chunk_.size());
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw std::ios_base::failure(std::strerror(errno));
      if (n == 0) return traits_type::eof();
      setg(chunk_.data(), chunk_.data(), chunk_.data() + n);
      return traits_type::to_int_type(*gptr());
    }
  }

 private:
  Fd file_;
  std::vector<char> chunk_;
};

// The stream and the buffer it reads, as one object.
class FileStream : public std::istream {
 public:
  explicit FileStream(Fd file) : std::istream(nullptr), buffer_(std::move(file)) { rdbuf(&buffer_); }

 private:
  FileBuffer buffer_;
};

}  // namespace

std::unique_ptr<std::istream> open_file_stream(const std::filesystem::path& path, std::size_t max_bytes) {
  Fd file{-1};
  open_checked(path, max_bytes, file);
  return std::make_unique<FileStream>(std::move(file));
}

RangedFile::RangedFile(const std::filesystem::path& path, std::size_t max_bytes) : path_(path) {
  Fd file{-1};
  size_ = open_checked(path, max_bytes, file);
  fd_ = std::exchange(file.fd, -1);
}

RangedFile::~RangedFile() { ::close(fd_); }

void RangedFile::read_at(std::uint64_t offset, std::span<char> out) const {
  std::size_t done = 0;
  while (done < out.size()) {
    const ssize_t n = ::pread(fd_, out.data() + done, out.size() - done, static_cast<off_t>(offset + done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path_, std::strerror(errno));
    if (n == 0) fail(path_, "it ended at byte " + std::to_string(offset + done) + " while being read (it shrank)");
    done += static_cast<std::size_t>(n);
  }
}

std::string read_file(const std::filesystem::path& path, std::size_t max_bytes) {
  Fd file{-1};
  const std::size_t size = open_checked(path, max_bytes, file);
  std::string bytes(size, '\0');
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(file.fd, bytes.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, std::strerror(errno));
    if (n == 0) break;  // shrank while read: what is there is the file
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace procex
