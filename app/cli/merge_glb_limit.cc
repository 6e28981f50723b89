#include "app/cli/merge_glb_limit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "app/cli/glb_size_estimate.h"
#include "core/io/glb_read.h"
#include "core/io/io_error.h"

namespace procex {
namespace {

// Parts named in the message; a merge of hundreds says how many more.
constexpr std::size_t kNamed = 8;

}  // namespace

void refuse_merge_past_glb_limit(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output,
                                 std::uint64_t max_bytes) {
  std::vector<std::uint64_t> claimed;
  std::uint64_t total = 0;
  for (const auto& p : parts) total += claimed.emplace_back(GlbReader::length(p));
  // The merged file holds the parts less what they share (the head, placed
  // meshes and images, once): no more than their sum, but for references
  // renumbered into longer numbers, which the writer's own check catches.
  if (total <= max_bytes) return;
  std::uint64_t at_least = 0;
  std::size_t read = 0;
  while (read < parts.size() && at_least <= max_bytes) at_least += GlbReader(parts[read++]).building_bytes();
  if (at_least <= max_bytes) return;  // parts that share much (large images): the writer judges
  std::string named;
  for (std::size_t i = 0; i < std::min(parts.size(), kNamed); ++i)
    named += (i ? ", " : "") + parts[i].string() + " " + byte_size_text(static_cast<double>(claimed[i]));
  if (parts.size() > kNamed) named += " and " + std::to_string(parts.size() - kNamed) + " more";
  // Groups each at most 90 % full, as batch advises for its shards.
  const auto groups = static_cast<std::uint64_t>(
      std::ceil(static_cast<double>(total) / (0.9 * static_cast<double>(max_bytes))));
  throw IoError("refused: the " + std::to_string(parts.size()) + " parts (" + named + ", " +
                    byte_size_text(static_cast<double>(total)) + " in all) hold " +
                    byte_size_text(static_cast<double>(at_least)) + " or more of buildings" +
                    (read < parts.size() ? " in the first " + std::to_string(read) + " alone" : "") + ", more than " +
                    glb_limit_text(max_bytes) + "; nothing written to " + output.string() +
                    ". Keep the shards as separate .glb files (each is a whole .glb of its buildings), or merge them "
                    "in groups of parts that stay under the limit (at least " + std::to_string(std::max<std::uint64_t>(groups, 2)) +
                    " groups), or run the batch into a folder of per-building files (-o FOLDER/)",
                output.string());
}

}  // namespace procex
