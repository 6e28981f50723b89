// file_version's answers kept for the length of one batch: every building of
// a batch hashes and reads the same meshes, material libraries and textures,
// and looking at each again (a stat, the absolute path, the version table)
// was a tenth of a city building's time (BENCHMARKS, Batch). It also keys
// and makes every building of a batch from one version of each file: a mesh
// saved while the batch runs is not placed on some buildings and not others.
// The studio keeps none, so an edited file is seen at the next evaluation.
#pragma once

#include <filesystem>
#include <shared_mutex>
#include <string>
#include <unordered_map>

#include "base/file_version.h"

namespace procex {

class FileVersionMemo {
 public:
  // file_version(file) as it was the first time this file was asked for.
  // Paths are taken as given: a batch names each file one way, from one
  // working directory. Thread-safe.
  FileVersion version(const std::filesystem::path& file);

 private:
  std::shared_mutex mutex_;
  std::unordered_map<std::string, FileVersion> versions_;
};

// memo's answer, or the file's own version where there is no memo.
inline FileVersion file_version(const std::filesystem::path& file, FileVersionMemo* memo) {
  return memo ? memo->version(file) : file_version(file);
}

}  // namespace procex
