// procex merge joins the shards' reports a building at a time
// (app/cli/report_merge.h): the merged report has the bytes of the one the
// whole parts parsed, joined and sorted give (the way merge made it before),
// parts that are not in feature order are refused, and the merge's peak
// memory does not follow the number of buildings.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli/merge_command.h"
#include "app/cli/report_text.h"
#include "tests/app/child_peak_memory.h"
#include "tests/app/command_test.h"
#include "tests/support/sanitizers.h"

namespace procex {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

// Shard `shard` of `shards` of a batch of `buildings`, as procex batch writes
// its report: the shard's stamp, and an entry per feature whose index is
// shard modulo shards, in feature order, with the members a batch gives it
// (statuses, warnings, tags and numbers of every kind varying by index).
void write_part(const fs::path& file, std::size_t shard, std::size_t shards, std::size_t buildings) {
  std::ofstream out(file);
  out << "{\n \"recipe\": \"samples/city.pxg\",\n \"footprints\": \"city \\\"old\\\" \\u00e9.geojson\",\n"
      << " \"output\": \"part" << shard << ".glb\",\n \"shard\": {\"index\": " << shard << ", \"count\": " << shards
      << ", \"recipe\": \"3f2a\", \"footprints\": \"9b1c\"},\n \"buildings\": [";
  static const char* kStatus[] = {"ok", "ok", "ok", "refused", "failed"};
  bool first = true;
  for (std::size_t i = shard; i < buildings; i += shards) {
    const char* status = kStatus[i % 5];
    out << (first ? "\n" : ",\n") << "  {\"index\": " << i << ", \"id\": \"way/" << 1000003 * i % 999983
        << "\", \"status\": \"" << status << "\", \"reason\": \""
        << (i % 5 == 3 ? "feature at /features/1/geometry: a ring needs 4 positions" : "") << "\", \"warnings\": ["
        << (i % 7 == 0 ? "\"Roof: a 0.2 m edge\\tkept\"" : "") << "], \"meshes\": " << i % 3
        << ", \"faces\": " << 40 + i % 97 << ", \"faces_per_tag\": {\"wall\": " << 20 + i % 13
        << ", \"roof\": " << i % 11 << ", \"window\": 0}, \"bounds\": {\"min\": [" << 40.0 * static_cast<double>(i % 1000)
        << ", -1e-7, 0], \"max\": [" << 0.1 * static_cast<double>(i) << ", 12.5, 1.7976931348623157e308]}, \"volume\": "
        << static_cast<double>(i) / 3.0 << ", \"placed\": {\"window\": " << i % 4 << "}, \"ms\": " << 0.25 * static_cast<double>(i % 9)
        << "}";
    first = false;
  }
  out << "\n ],\n \"summary\": {\"buildings\": 0, \"ok\": 0, \"refused\": 0, \"failed\": 0, \"ms\": 12.5}\n}\n";
}

// The merged report as merge made it before it was streamed: every part
// parsed whole, the buildings joined and sorted stably by feature index, the
// summary recounted.
std::string merged_whole(const std::vector<fs::path>& parts) {
  json merged, buildings = json::array();
  for (const fs::path& file : parts) {
    json part = json::parse(test::read_text(file));
    if (merged.empty())
      for (const char* key : {"recipe", "footprints"}) merged[key] = part.value(key, "");
    for (json& b : part["buildings"]) buildings.push_back(std::move(b));
  }
  std::stable_sort(buildings.begin(), buildings.end(),
                   [](const json& a, const json& b) { return a["index"].get<std::size_t>() < b["index"].get<std::size_t>(); });
  std::size_t counts[3] = {0, 0, 0};
  for (const json& b : buildings) {
    const std::string s = b.value("status", "");
    ++counts[s == "ok" ? 0 : s == "refused" ? 1 : 2];
  }
  const json stamp = json::parse(test::read_text(parts.front()))["shard"];
  merged["shard"] = {{"index", 0}, {"count", 1}, {"recipe", stamp["recipe"]}, {"footprints", stamp["footprints"]}};
  merged["buildings"] = std::move(buildings);
  merged["summary"] = {{"buildings", merged["buildings"].size()}, {"ok", counts[0]}, {"refused", counts[1]}, {"failed", counts[2]}};
  return report_text(merged);
}

class MergeReportStream : public test::CommandTest {
 protected:
  std::vector<fs::path> parts(std::size_t shards, std::size_t buildings, const std::string& name = "part") {
    std::vector<fs::path> files;
    for (std::size_t s = 0; s < shards; ++s) {
      files.push_back(dir_ / (name + std::to_string(s) + ".json"));
      write_part(files.back(), s, shards, buildings);
    }
    return files;
  }
};

TEST_F(MergeReportStream, ManyShardsMergeIntoTheReportMadeWhole) {
  for (const auto& [shards, buildings] : {std::pair<std::size_t, std::size_t>{16, 5000}, {3, 7}, {5, 3}}) {
    SCOPED_TRACE(std::to_string(shards) + " shards of " + std::to_string(buildings));
    std::vector<fs::path> files = parts(shards, buildings);
    std::reverse(files.begin(), files.end());  // given in any order
    MergeCommandOptions merge{files, dir_ / "merged.glb", dir_ / "merged.json"};
    ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
    EXPECT_TRUE(test::read_text(merge.report) == merged_whole(files));
  }
}

// A part whose "buildings" member is given twice: the last one counts, as it did parsed whole.
TEST_F(MergeReportStream, ARepeatedBuildingsMemberCountsOnceAsBefore) {
  std::vector<fs::path> files = parts(2, 40);
  std::string text = test::read_text(files[1]);
  text.insert(text.find("\"buildings\""), "\"buildings\": [{\"index\": 99, \"status\": \"ok\"}],\n ");
  std::ofstream(files[1]) << text;
  MergeCommandOptions merge{files, dir_ / "merged.glb", dir_ / "merged.json"};
  ASSERT_EQ(run_merge(merge, out_, err_), 0) << err_.str();
  EXPECT_TRUE(test::read_text(merge.report) == merged_whole(files));
  EXPECT_EQ(json::parse(test::read_text(merge.report))["summary"]["buildings"], 40);
}

TEST_F(MergeReportStream, APartOutOfFeatureOrderIsRefused) {
  std::vector<fs::path> files = parts(2, 40);
  std::string text = test::read_text(files[0]);
  const std::size_t second = text.find("{\"index\": 2,"), third = text.find("{\"index\": 4,");
  std::swap_ranges(text.begin() + second, text.begin() + second + 12, text.begin() + third);  // 4 before 2
  std::ofstream(files[0]) << text;
  MergeCommandOptions merge{files, dir_ / "merged.glb", dir_ / "merged.json"};
  EXPECT_EQ(run_merge(merge, out_, err_), 2);
  EXPECT_NE(err_.str().find(files[0].string() + ": /buildings/2/index: feature 2 after feature 4"), std::string::npos)
      << err_.str();
  EXPECT_FALSE(fs::exists(merge.report));
}

// Peak RSS in KiB of `procex merge` of the parts' reports alone.
long merge_peak_kib(const std::vector<fs::path>& files, const fs::path& output) {
  std::vector<std::string> args = {"merge"};
  for (const fs::path& f : files) args.push_back(f.string());
  for (const std::string& a : {std::string("-o"), output.string() + ".glb", std::string("--report"), output.string() + ".json"})
    args.push_back(a);
  return test::procex_peak_kib(args);
}

// Parsed whole, each entry took about 3 KB of nlohmann's values: 100,000
// buildings over 10,000 were some 270 MB more. Streamed, memory holds an
// entry per part and the parts' small members.
TEST_F(MergeReportStream, PeakMemoryDoesNotFollowTheBuildings) {
  if (kSanitized) GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine are not the program's";
  const long few_kib = merge_peak_kib(parts(4, 10000, "few"), dir_ / "few");
  const long many_kib = merge_peak_kib(parts(4, 100000, "many"), dir_ / "many");
  EXPECT_EQ(json::parse(test::read_text(dir_ / "many.json"))["summary"]["buildings"], 100000);
  const double growth_mb = static_cast<double>(many_kib - few_kib) / 1024;
  EXPECT_LT(growth_mb, 20) << "peak " << few_kib / 1024 << " MB at 10,000 buildings, " << many_kib / 1024
                           << " MB at 100,000";
}

}  // namespace
}  // namespace procex
