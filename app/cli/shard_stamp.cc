#include "app/cli/shard_stamp.h"

#include <map>

#include "core/io/io_error.h"

namespace procex {
namespace {

[[noreturn]] void not_a_stamp(const std::filesystem::path& file, const std::string& pointer, const std::string& what) {
  throw IoError(file.string() + ": " + pointer + ": " + what + " (not a shard of procex batch)", file.string(), pointer);
}

}  // namespace

nlohmann::ordered_json to_json(const ShardStamp& stamp) {
  return {{"index", stamp.index}, {"count", stamp.count}, {"recipe", stamp.recipe}, {"footprints", stamp.footprints}};
}

ShardStamp read_shard_stamp(const nlohmann::ordered_json& object, const std::filesystem::path& file,
                            const std::string& pointer) {
  if (!object.is_object()) not_a_stamp(file, pointer, "expected the shard's index, count, recipe and footprints");
  ShardStamp stamp;
  for (auto [key, to] : {std::pair{"index", &stamp.index}, std::pair{"count", &stamp.count}}) {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_number_unsigned()) not_a_stamp(file, pointer + "/" + key, "expected a whole number");
    *to = it->get<std::size_t>();
  }
  for (auto [key, to] : {std::pair{"recipe", &stamp.recipe}, std::pair{"footprints", &stamp.footprints}}) {
    const auto it = object.find(key);
    if (it == object.end() || !it->is_string()) not_a_stamp(file, pointer + "/" + key, "expected the hash of the file");
    *to = it->get<std::string>();
  }
  if (stamp.count == 0 || stamp.index >= stamp.count) not_a_stamp(file, pointer, "the index must be below the count");
  return stamp;
}

void check_whole(const std::vector<std::pair<ShardStamp, std::filesystem::path>>& shards) {
  if (shards.empty()) return;
  const auto& [first, first_file] = shards.front();
  std::map<std::size_t, const std::filesystem::path*> seen;  // not a vector of `count`: the count is the file's word
  for (const auto& [id, file] : shards) {
    auto refuse = [&](const std::string& why) {
      throw IoError(file.string() + ": " + why + ", so the parts are not one whole batch: merge the parts of one run, "
                                                 "each of its shards once",
                    file.string(), "/shard");
    };
    if (id.count != first.count)
      refuse("shard " + std::to_string(id.index) + " of " + std::to_string(id.count) + ", but " + first_file.string() +
             " is one of " + std::to_string(first.count));
    if (id.recipe != first.recipe || id.footprints != first.footprints)
      refuse("made from another recipe, footprint file or streets file than " + first_file.string());
    if (const auto [it, fresh] = seen.emplace(id.index, &file); !fresh)
      refuse("shard " + std::to_string(id.index) + " again (also " + it->second->string() + ")");
  }
  for (std::size_t i = 0; seen.size() < first.count; ++i)
    if (!seen.count(i))
      throw IoError("shard " + std::to_string(i) + " of " + std::to_string(first.count) +
                        " is missing: merge needs every shard's part",
                    first_file.string(), "/shard");
}

}  // namespace procex
