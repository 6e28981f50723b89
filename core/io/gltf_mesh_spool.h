// Buildings of glTF scenes set aside on disk and read back one at a time, in
// any order: what procex merge holds of its parts while it puts their
// buildings in feature order, instead of every part's buildings in memory.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "base/spool_file.h"
#include "core/io/gltf_write.h"

namespace procex {

class GltfMeshSpool {
 public:
  // Where a building was put.
  struct Place {
    std::uint64_t offset = 0;
    std::uint64_t length = 0;
  };
  // Set aside in `folder` (beside what they are read back for). Throws
  // IoError naming it if no temporary file can be made there.
  explicit GltfMeshSpool(const std::string& folder) : spool_(folder) {}
  // Throws IoError if the temporary folder is full.
  Place add(const GltfMeshData& mesh);
  // The building as added (an image shared by buildings is shared again).
  GltfMeshData get(Place at) const;

 private:
  SpoolFile spool_;
  // Material images, each once (they are few, and shared by many buildings).
  std::vector<std::shared_ptr<const std::string>> images_;
};

}  // namespace procex
