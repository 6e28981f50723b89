#include "base/file_version.h"

#include <chrono>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <string_view>

#include "base/read_file.h"

namespace procex {

FileVersion file_version(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  // A version hashed this long after its time is not written again unseen.
  constexpr auto kSettled = std::chrono::seconds(2);
  struct Hashed {
    FileVersion version;
    bool settled;
  };
  static std::mutex mutex;
  static std::map<std::string, Hashed> hashed;

  FileVersion v;
  std::error_code size_error, time_error, type_error;
  const auto size = fs::file_size(file, size_error);
  const auto time = fs::last_write_time(file, time_error);
  if (size_error || time_error || !fs::is_regular_file(file, type_error)) return v;
  v.size = size;
  v.time = time.time_since_epoch().count();
  const std::string key = fs::absolute(file).string();
  {
    std::lock_guard lock(mutex);
    if (const auto it = hashed.find(key); it != hashed.end() && it->second.settled && it->second.version.size == v.size &&
                                          it->second.version.time == v.time)
      return it->second.version;
  }
  const bool settled = fs::file_time_type::clock::now() - time > kSettled;  // judged before the read
  try {
    v.content = std::hash<std::string_view>()(read_file(file, kMaxDataFileBytes)) | 1;  // 0 is "unread"
  } catch (const IoError&) {
    return v;
  }
  std::lock_guard lock(mutex);
  if (hashed.size() >= 1024) hashed.clear();  // edited files leave old versions behind
  hashed[key] = {v, settled};
  return v;
}

}  // namespace procex
