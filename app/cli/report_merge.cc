#include "app/cli/report_merge.h"

#include <cstdint>
#include <cstring>
#include <memory>
#include <queue>
#include <utility>

#include "app/cli/shard_stamp.h"
#include "base/spool_file.h"
#include "core/io/io_error.h"
#include "core/io/json_read.h"

namespace procex {
namespace {

using json = nlohmann::ordered_json;

[[noreturn]] void not_a_report(const std::filesystem::path& file, const std::string& pointer, const std::string& what) {
  throw IoError(file.string() + ": " + pointer + ": " + what + " (not a procex batch report)", file.string(), pointer);
}

// A member that must be a string; the report is someone's file, so every
// type is checked before it is used.
std::string text_member(const json& object, const char* key, const std::filesystem::path& file, const std::string& pointer) {
  const auto it = object.find(key);
  if (it == object.end()) return {};
  if (!it->is_string()) not_a_report(file, pointer + "/" + key, "expected a string");
  return it->get<std::string>();
}

// One part's entries, rendered, in its order: records of the feature index
// and the text's length (8 bytes each) and the text, read back one at a time.
struct PartEntries {
  explicit PartEntries(const std::string& folder) : records(std::make_unique<SpoolFile>(folder)) {}
  std::unique_ptr<SpoolFile> records;
  std::size_t count = 0, counts[3] = {0, 0, 0};  // ok, refused, failed
  std::uint64_t next = 0;                         // where the next record to read back starts

  void add(std::uint64_t index, const std::string& text) {
    const std::uint64_t head[2] = {index, text.size()};
    records->append(std::string_view(reinterpret_cast<const char*>(head), sizeof head));
    records->append(text);
    ++count;
  }
  // The next record's feature index and text length.
  std::pair<std::uint64_t, std::uint64_t> peek() const {
    const std::string bytes = records->read_at(next, 2 * sizeof(std::uint64_t));
    std::uint64_t head[2];
    std::memcpy(head, bytes.data(), sizeof head);
    return {head[0], head[1]};
  }
  std::string take(std::uint64_t length) {
    std::string text = records->read_at(next + 2 * sizeof(std::uint64_t), length);
    next += 2 * sizeof(std::uint64_t) + length;
    return text;
  }
};

}  // namespace

MergedReport::MergedReport(const std::vector<std::filesystem::path>& files, const std::string& folder)
    : entries_(folder) {
  std::vector<PartEntries> parts;
  for (std::size_t p = 0; p < files.size(); ++p) parts.emplace_back(folder);
  std::vector<std::pair<ShardStamp, std::filesystem::path>> shards;
  for (std::size_t p = 0; p < files.size(); ++p) {
    const std::filesystem::path& file = files[p];
    PartEntries& part = parts[p];
    std::uint64_t last = 0;
    const json doc = io_detail::parse_json_file<json>(
        file, io_detail::elements_of<json>(
                  "buildings", [&] { part = PartEntries(folder); },
                  [&](const json& b, std::size_t i) {
                    const std::string pointer = "/buildings/" + std::to_string(i);
                    if (!b.is_object()) not_a_report(file, pointer, "expected an object");
                    const auto index = b.find("index");
                    if (index == b.end() || !index->is_number_unsigned())
                      not_a_report(file, pointer + "/index", "expected a feature index");
                    const std::uint64_t at = index->get<std::uint64_t>();
                    // A shard lists its buildings as it made them, in feature
                    // order: the parts are joined, never sorted whole.
                    if (part.count > 0 && at < last)
                      not_a_report(file, pointer + "/index",
                                   "feature " + std::to_string(at) + " after feature " + std::to_string(last) +
                                       ": a report lists its buildings in feature order");
                    last = at;
                    const std::string status = text_member(b, "status", file, pointer);
                    ++part.counts[status == "ok" ? 0 : status == "refused" ? 1 : 2];
                    part.add(at, ReportEntries::text(b));
                  }));
    if (!doc.is_object()) not_a_report(file, "", "expected an object");
    const auto stamp = doc.find("shard");
    shards.emplace_back(read_shard_stamp(stamp == doc.end() ? json() : *stamp, file, "/shard"), file);
    const auto list = doc.find("buildings");
    if (list == doc.end() || !list->is_array()) not_a_report(file, "/buildings", "expected an array");
    if (p == 0)
      for (const char* key : {"recipe", "footprints"}) report_[key] = text_member(doc, key, file, "");
  }
  check_whole(shards);
  if (!shards.empty()) {
    report_["shard"] = to_json(whole_run(shards.front().first));
    shard_ = report_["shard"].dump();
  }
  // The parts' entries in feature order, those of one feature in the parts'
  // order: what sorting them all together (stably) gave.
  using Next = std::pair<std::uint64_t, std::size_t>;  // feature index, part
  std::priority_queue<Next, std::vector<Next>, std::greater<>> heads;
  std::vector<std::uint64_t> lengths(parts.size());
  std::vector<std::size_t> left(parts.size());
  const auto queue = [&](std::size_t p) {
    if (left[p] == 0) return;
    const auto [index, length] = parts[p].peek();
    lengths[p] = length;
    heads.push({index, p});
  };
  std::size_t counts[3] = {0, 0, 0};
  for (std::size_t p = 0; p < parts.size(); ++p) {
    left[p] = parts[p].count;
    for (int k = 0; k < 3; ++k) counts[k] += parts[p].counts[k];
    queue(p);
  }
  while (!heads.empty()) {
    const std::size_t p = heads.top().second;
    heads.pop();
    entries_.add(parts[p].take(lengths[p]));
    --left[p];
    queue(p);
  }
  report_["buildings"] = json::array();
  report_["summary"] = {{"buildings", entries_.count()}, {"ok", counts[0]}, {"refused", counts[1]}, {"failed", counts[2]}};
}

}  // namespace procex
