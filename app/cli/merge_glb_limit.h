// A merge whose parts' buildings are more than one .glb holds (glTF's 4 GiB)
// is refused before any building is read: the parts' headers give what they
// claim; past the limit, each part's JSON is indexed (no building read) for
// what its buildings take at least, and the merge is refused once those pass
// it. The streamed writer stopped such a merge only when the merged file
// passed the limit, after every part had been read and set aside on disk.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "core/io/gltf_write.h"

namespace procex {

// Throws IoError naming the parts, what they take and what to do instead
// (keep the shards as separate files, or merge them in smaller groups), or
// naming a part that is not a .glb as procex writes it. max_bytes: what the
// merged file may hold, kGlbMaxBytes but in tests.
void refuse_merge_past_glb_limit(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output,
                                 std::uint64_t max_bytes = kGlbMaxBytes);

}  // namespace procex
