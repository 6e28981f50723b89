// What a batch shard says it is, in its report and in its .glb (the scene's
// extras): which of how many, of which recipe and footprint file (hashes of
// their bytes). procex merge joins only a set of shards that is exactly one
// whole run.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace procex {

struct ShardStamp {
  std::size_t index = 0, count = 1;
  std::string recipe, footprints;
};

// {"index": i, "count": N, "recipe": hash, "footprints": hash}: a report's
// "shard" member and a .glb scene's extras.shard, the same text in both.
nlohmann::ordered_json to_json(const ShardStamp& stamp);

// The stamp in `object` (someone's file: every member's type is checked).
// Throws IoError naming file and `pointer` (where object sits in it).
ShardStamp read_shard_stamp(const nlohmann::ordered_json& object, const std::filesystem::path& file,
                            const std::string& pointer);

// What the parts of one run are together: the one shard of an unsharded run.
inline ShardStamp whole_run(const ShardStamp& part) { return {0, 1, part.recipe, part.footprints}; }

// Throws IoError unless the stamps are one of each index of the same count,
// from the same recipe and footprints: a shard twice, one missing, shards of
// two splits or two runs would merge into a file that looks complete and is
// not.
void check_whole(const std::vector<std::pair<ShardStamp, std::filesystem::path>>& shards);

}  // namespace procex
