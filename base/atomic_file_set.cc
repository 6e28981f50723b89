#include "base/atomic_file_set.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <mutex>

namespace procex {

namespace {

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int error) {
  throw IoError("cannot write '" + path.string() + "': " + what + ": " + std::strerror(error), path.string());
}

// Temporary files being written, for the signal handler to remove: fixed
// slots of path copies, since a handler may neither allocate nor lock.
constexpr std::size_t kSlots = 256, kPathBytes = PATH_MAX;
char g_paths[kSlots][kPathBytes];
std::atomic<bool> g_used[kSlots];
std::mutex g_claim;

void remove_temporaries(int signal) {
  for (std::size_t i = 0; i < kSlots; ++i)
    if (g_used[i].load()) ::unlink(g_paths[i]);
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

// Installed once, the first time a file is written: only then is there
// anything to clean up, and a program that never writes keeps its handlers.
void install_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int s : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      ::sigaction(s, nullptr, &old);
      if (old.sa_handler == SIG_DFL) ::signal(s, remove_temporaries);  // keep a handler the program set
    }
  });
}

// The slot a temporary file's path is kept in while it exists; kSlots when
// all are taken (more files than that at once: the file is simply not
// removed on a signal).
std::size_t remember(const std::filesystem::path& temp) {
  install_handlers();
  const std::string& s = temp.native();
  if (s.size() >= kPathBytes) return kSlots;
  std::lock_guard lock(g_claim);
  for (std::size_t i = 0; i < kSlots; ++i)
    if (!g_used[i].load()) {
      std::memcpy(g_paths[i], s.c_str(), s.size() + 1);
      g_used[i].store(true);
      return i;
    }
  return kSlots;
}

void forget(const std::filesystem::path& temp) {
  std::lock_guard lock(g_claim);
  for (std::size_t i = 0; i < kSlots; ++i)
    if (g_used[i].load() && temp.native() == g_paths[i]) {
      g_used[i].store(false);
      return;
    }
}

// Writes every piece, syncs and closes; throws after removing temp on failure.
void write_all(int fd, const std::filesystem::path& path, const std::filesystem::path& temp,
               std::span<const FilePiece> pieces) {
  auto give_up = [&](const std::string& what, int error) {
    ::close(fd);
    ::unlink(temp.c_str());
    forget(temp);
    fail(path, what, error);
  };
  // Bytes in memory up to IOV_MAX pieces per writev; a short write resumes inside its piece.
  std::vector<iovec> iov;
  const auto write_iov = [&] {
    for (std::size_t first = 0; first < iov.size();) {
      const int count = static_cast<int>(std::min<std::size_t>(iov.size() - first, IOV_MAX));
      const ssize_t n = ::writev(fd, iov.data() + first, count);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) give_up("write failed", n < 0 ? errno : EIO);  // 0 for a non-empty request would loop forever
      for (auto done = static_cast<std::size_t>(n); done > 0;) {
        const std::size_t step = std::min(done, iov[first].iov_len);
        iov[first].iov_base = static_cast<char*>(iov[first].iov_base) + step;
        iov[first].iov_len -= step;
        done -= step;
        if (iov[first].iov_len == 0) ++first;
      }
    }
    iov.clear();
  };
  for (const FilePiece& piece : pieces) {
    if (!piece.spool) {
      if (!piece.bytes.empty()) iov.push_back({const_cast<char*>(piece.bytes.data()), piece.bytes.size()});
      continue;
    }
    write_iov();
    try {
      piece.spool->read([&](std::string_view chunk) {
        iov.push_back({const_cast<char*>(chunk.data()), chunk.size()});
        write_iov();
      });
    } catch (const IoError& e) {
      ::close(fd);
      ::unlink(temp.c_str());
      forget(temp);
      throw IoError("cannot write '" + path.string() + "': " + e.what(), path.string());
    }
  }
  write_iov();
  // On disk before the rename makes it the file: a crash then leaves the old
  // file or the new one, never an empty one.
  if (::fsync(fd) != 0) give_up("sync failed", errno);
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temp.c_str());
    forget(temp);
    fail(path, "close failed", error);
  }
}

void sync_folder(const std::filesystem::path& path) {
  const std::filesystem::path folder = path.parent_path().empty() ? "." : path.parent_path();
  const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;  // the rename is done; a folder that cannot be opened only loses durability
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

AtomicFileSet::~AtomicFileSet() {
  for (const Staged& s : staged_) {
    ::unlink(s.temp.c_str());
    forget(s.temp);
  }
}

void AtomicFileSet::add(const std::filesystem::path& path, std::string_view contents) {
  add(path, std::span<const std::string_view>(&contents, 1));
}

void AtomicFileSet::add(const std::filesystem::path& path, std::span<const std::string_view> pieces) {
  std::vector<FilePiece> all;
  all.reserve(pieces.size());
  for (std::string_view piece : pieces) all.push_back({piece});
  add(path, all);
}

void AtomicFileSet::add(const std::filesystem::path& path, std::span<const FilePiece> pieces) {
  // Unique per process and call, so concurrent writers never share a temp file.
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temp = path;
  temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  remember(temp);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int error = errno;
    forget(temp);
    fail(path, "cannot create '" + temp.string() + "'", error);
  }
  write_all(fd, path, temp, pieces);
  const auto same = std::find_if(staged_.begin(), staged_.end(), [&](const Staged& s) { return s.target == path; });
  if (same != staged_.end()) {
    ::unlink(same->temp.c_str());
    forget(same->temp);
    same->temp = std::move(temp);
  } else {
    staged_.push_back({path, std::move(temp)});
  }
}

void AtomicFileSet::commit() {
  // A folder where a file should go is the one failure a rename meets that
  // can be seen before any file is renamed.
  for (const Staged& s : staged_) {
    std::error_code ec;
    if (std::filesystem::is_directory(s.target, ec)) fail(s.target, "it is a folder", EISDIR);
  }
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    const Staged& s = staged_[i];
    if (::rename(s.temp.c_str(), s.target.c_str()) != 0) {
      const int error = errno;
      staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(i));  // those are in place
      fail(s.target, "cannot rename '" + s.temp.string() + "' over it", error);
    }
    forget(s.temp);
    sync_folder(s.target);
  }
  staged_.clear();
}

}  // namespace procex
