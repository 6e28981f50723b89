// confined_path's answers kept for the length of one batch: every building of
// a batch names the same textures and meshes, and resolving a name again
// (realpath's walk of each folder, a readlink per symlink) was a third of what
// four Material nodes added to a batch (BENCHMARKS, Batch). A name is
// resolved and checked the first time it is asked for; a refused one is
// asked again (and refused again) each time, so nothing outside the folder is
// ever let through. What it does not see: a symlink edited while the memo
// lives, which is why only a batch keeps one and the studio does not.
#pragma once

#include <filesystem>
#include <shared_mutex>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>

#include "base/confined_path.h"

namespace procex {

class ConfinedPathMemo {
 public:
  // confined_path(root, name, allowed), the same path or the same IoError,
  // resolved once per root, name and allowed folders. Thread-safe.
  std::filesystem::path resolve(const std::filesystem::path& root, std::string_view name,
                                std::span<const std::filesystem::path> allowed = {});

 private:
  std::shared_mutex mutex_;
  std::unordered_map<std::string, std::filesystem::path> resolved_;
};

}  // namespace procex
