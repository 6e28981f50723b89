#include "base/atomic_write.h"

#include "base/atomic_file_set.h"

namespace procex {

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path, std::span<const std::string_view>(&contents, 1));
}

void write_file_atomically(const std::filesystem::path& path, std::span<const std::string_view> pieces) {
  AtomicFileSet file;
  file.add(path, pieces);
  file.commit();
}

void write_file_atomically(const std::filesystem::path& path, std::span<const FilePiece> pieces) {
  AtomicFileSet file;
  file.add(path, pieces);
  file.commit();
}

}  // namespace procex
