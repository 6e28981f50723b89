#include "app/cli/merge_command.h"

#include <algorithm>
#include <ostream>

#include <nlohmann/json.hpp>

#include "app/cli/output_paths.h"
#include "app/cli/recipe_session.h"
#include "app/cli/report_text.h"
#include "base/atomic_file_set.h"
#include "core/io/gltf_write.h"
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

// A report's shard: which of how many, of which recipe and footprints (by
// the hashes of their bytes).
struct ShardId {
  std::size_t index = 0, count = 0;
  std::string recipe, footprints;
};

ShardId shard_of(const json& report, const std::filesystem::path& file) {
  const auto shard = report.find("shard");
  if (shard == report.end() || !shard->is_object()) not_a_report(file, "/shard", "expected the shard's index and count");
  ShardId id;
  for (auto [key, to] : {std::pair{"index", &id.index}, std::pair{"count", &id.count}}) {
    const auto it = shard->find(key);
    if (it == shard->end() || !it->is_number_unsigned()) not_a_report(file, std::string("/shard/") + key, "expected a whole number");
    *to = it->get<std::size_t>();
  }
  id.recipe = text_member(*shard, "recipe", file, "/shard");
  id.footprints = text_member(*shard, "footprints", file, "/shard");
  if (id.count == 0 || id.index >= id.count) not_a_report(file, "/shard", "the index must be below the count");
  return id;
}

// The shards must be exactly one whole: one of each index of the same count,
// from the same recipe and footprints. Anything else (a shard twice, one
// missing, shards of two different splits or runs) would merge into a file
// that looks complete and is not.
void check_whole(const std::vector<std::pair<ShardId, std::filesystem::path>>& shards) {
  if (shards.empty()) return;
  const auto& [first, first_file] = shards.front();
  std::vector<const std::filesystem::path*> seen(first.count, nullptr);
  for (const auto& [id, file] : shards) {
    auto refuse = [&](const std::string& why) {
      throw IoError(file.string() + ": " + why + ", so the parts are not one whole batch: merge the reports of one run, "
                                                 "each of its shards once",
                    file.string(), "/shard");
    };
    if (id.count != first.count)
      refuse("shard " + std::to_string(id.index) + " of " + std::to_string(id.count) + ", but " + first_file.string() +
             " is one of " + std::to_string(first.count));
    if (id.recipe != first.recipe || id.footprints != first.footprints)
      refuse("made from another recipe or footprint file than " + first_file.string());
    if (seen[id.index]) refuse("shard " + std::to_string(id.index) + " again (also " + seen[id.index]->string() + ")");
    seen[id.index] = &file;
  }
  for (std::size_t i = 0; i < seen.size(); ++i)
    if (!seen[i])
      throw IoError("shard " + std::to_string(i) + " of " + std::to_string(first.count) +
                        " is missing: merge needs the report of every shard",
                    first_file.string(), "/shard");
}

// Reports: checked to be one whole batch, buildings joined and sorted by
// feature index, the summary recounted.
json merge_reports(const std::vector<std::filesystem::path>& files) {
  json merged;
  json buildings = json::array();
  std::vector<std::pair<ShardId, std::filesystem::path>> shards;
  for (const auto& file : files) {
    json part = read_json_file(file);
    if (!part.is_object()) not_a_report(file, "", "expected an object");
    shards.emplace_back(shard_of(part, file), file);
    const auto list = part.find("buildings");
    if (list == part.end() || !list->is_array()) not_a_report(file, "/buildings", "expected an array");
    if (merged.empty())
      for (const char* key : {"recipe", "footprints"}) merged[key] = text_member(part, key, file, "");
    for (std::size_t i = 0; i < list->size(); ++i) {
      json& b = (*list)[i];
      const std::string pointer = "/buildings/" + std::to_string(i);
      if (!b.is_object()) not_a_report(file, pointer, "expected an object");
      if (!b.contains("index") || !b["index"].is_number_unsigned()) not_a_report(file, pointer + "/index", "expected a feature index");
      text_member(b, "status", file, pointer);
      buildings.push_back(std::move(b));
    }
  }
  check_whole(shards);
  std::stable_sort(buildings.begin(), buildings.end(),
                   [](const json& a, const json& b) { return a["index"].get<std::size_t>() < b["index"].get<std::size_t>(); });
  std::size_t counts[3] = {0, 0, 0};
  for (const json& b : buildings) {
    const std::string s = b.value("status", "");
    ++counts[s == "ok" ? 0 : s == "refused" ? 1 : 2];
  }
  merged["shard"] = {{"index", 0}, {"count", 1}};
  if (!shards.empty()) merged["shard"].update({{"recipe", shards[0].first.recipe}, {"footprints", shards[0].first.footprints}});
  merged["buildings"] = std::move(buildings);
  merged["summary"] = {{"buildings", merged["buildings"].size()}, {"ok", counts[0]}, {"refused", counts[1]}, {"failed", counts[2]}};
  return merged;
}

}  // namespace

int run_merge(const MergeCommandOptions& options, std::ostream& out, std::ostream& err) {
  std::vector<std::filesystem::path> meshes, reports;
  for (const auto& p : options.parts) (p.extension() == ".json" ? reports : meshes).push_back(p);
  if (options.output.extension() != ".glb") {
    err << "procex merge: " << options.output.string() << ": merging writes .glb (batch shards with -o PART.glb)\n";
    return kExitUnusableInput;
  }
  if (const auto clash = output_clash(options.parts, {options.output, options.report})) {
    err << "procex merge: " << *clash << "\n";
    return kExitUnusableInput;
  }
  if (!reports.empty() && options.report.empty()) {
    err << "procex merge: report parts given (" << reports.front().string() << "...) but no --report to write\n";
    return kExitUnusableInput;
  }
  try {
    // Each part's placed meshes come along (renumbered); write_glb keeps one
    // of equal ones, so the bytes are those of an unsharded run.
    GltfScene all;
    for (const auto& p : meshes) {
      if (p.extension() != ".glb") throw IoError(p.string() + ": only .glb shard outputs can be merged", p.string());
      append_scene(all, read_glb_scene(p));
    }
    std::stable_sort(all.meshes.begin(), all.meshes.end(),
                     [](const GltfMeshData& a, const GltfMeshData& b) { return a.feature < b.feature; });
    // A feature in two parts: the same shard given twice, or parts of different splits.
    for (std::size_t i = 1; i < all.meshes.size(); ++i)
      if (all.meshes[i].feature >= 0 && all.meshes[i].feature == all.meshes[i - 1].feature)
        throw IoError("feature " + std::to_string(all.meshes[i].feature) + " (" + all.meshes[i].building +
                          ") is in two parts: give each shard once, all from one run",
                      options.output.string());
    if (!reports.empty() && reports.size() != meshes.size() && !meshes.empty())
      throw IoError(std::to_string(meshes.size()) + " .glb parts but " + std::to_string(reports.size()) +
                        " reports: give the mesh and the report of every shard",
                    options.output.string());
    // Both or neither: the report is read, merged and written beside its
    // target before the mesh, and put in place once the mesh is.
    AtomicFileSet report_file;
    if (!options.report.empty()) report_file.add(options.report, report_text(merge_reports(reports)));
    write_glb(options.output, all);
    report_file.commit();
    out << "procex merge: " << meshes.size() << " parts, " << all.meshes.size() << " meshes -> " << options.output.string() << "\n";
  } catch (const IoError& e) {
    err << "procex merge: " << e.what() << "\n";
    return kExitUnusableInput;
  }
  return 0;
}

}  // namespace procex
