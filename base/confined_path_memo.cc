#include "base/confined_path_memo.h"

#include <mutex>

namespace procex {

std::filesystem::path ConfinedPathMemo::resolve(const std::filesystem::path& root, std::string_view name,
                                                std::span<const std::filesystem::path> allowed) {
  // Everything confined_path's answer depends on; no path holds a NUL.
  std::string key = root.native();
  key.append(1, '\0').append(name);
  for (const std::filesystem::path& a : allowed) key.append(1, '\0').append(a.native());
  {
    std::shared_lock lock(mutex_);
    if (const auto it = resolved_.find(key); it != resolved_.end()) return it->second;
  }
  std::filesystem::path path = confined_path(root, name, allowed);  // throws for a refused name: not kept
  std::unique_lock lock(mutex_);
  return resolved_.try_emplace(std::move(key), std::move(path)).first->second;
}

}  // namespace procex
