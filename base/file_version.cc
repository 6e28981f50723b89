#include "base/file_version.h"

#include <sys/stat.h>

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
  // One stat for type, size and time (std::filesystem asks three times): a
  // batch asks for each building's textures and placed meshes.
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return v;
  v.size = static_cast<std::uintmax_t>(st.st_size);
  const auto time = std::chrono::system_clock::time_point(std::chrono::duration_cast<std::chrono::system_clock::duration>(
      std::chrono::seconds(st.st_mtim.tv_sec) + std::chrono::nanoseconds(st.st_mtim.tv_nsec)));
  v.time = std::chrono::duration_cast<std::chrono::nanoseconds>(time.time_since_epoch()).count();
  const std::string key = fs::absolute(file).string();
  {
    std::lock_guard lock(mutex);
    if (const auto it = hashed.find(key); it != hashed.end() && it->second.settled && it->second.version.size == v.size &&
                                          it->second.version.time == v.time)
      return it->second.version;
  }
  const bool settled = std::chrono::system_clock::now() - time > kSettled;  // judged before the read
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
