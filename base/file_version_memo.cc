#include "base/file_version_memo.h"

#include <mutex>

namespace procex {

FileVersion FileVersionMemo::version(const std::filesystem::path& file) {
  {
    std::shared_lock lock(mutex_);
    if (const auto it = versions_.find(file.native()); it != versions_.end()) return it->second;
  }
  const FileVersion v = file_version(file);
  std::unique_lock lock(mutex_);
  return versions_.try_emplace(file.native(), v).first->second;  // a racing first answer wins for everyone
}

}  // namespace procex
