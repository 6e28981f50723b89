#include "app/cli/merge_command.h"

#include <algorithm>
#include <fstream>
#include <ostream>

#include <nlohmann/json.hpp>

#include "app/cli/recipe_session.h"
#include "core/io/atomic_write.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"

namespace procex {
namespace {

using json = nlohmann::ordered_json;

// Reports: buildings joined and sorted by feature index, the summary recounted.
json merge_reports(const std::vector<std::filesystem::path>& files) {
  json merged;
  json buildings = json::array();
  for (const auto& file : files) {
    std::ifstream in(file);
    if (!in) throw IoError("cannot open '" + file.string() + "'", file.string());
    json part;
    try {
      part = json::parse(in);
    } catch (const json::exception& e) {
      throw IoError(file.string() + ": not JSON: " + e.what(), file.string());
    }
    if (!part.contains("buildings") || !part["buildings"].is_array())
      throw IoError(file.string() + ": /buildings: not a procex batch report", file.string(), "/buildings");
    if (merged.empty())
      for (const char* key : {"recipe", "footprints"}) merged[key] = part.value(key, "");
    for (auto& b : part["buildings"]) {
      if (!b.contains("index") || !b["index"].is_number_unsigned())
        throw IoError(file.string() + ": a building without an index", file.string(), "/buildings");
      buildings.push_back(std::move(b));
    }
  }
  std::stable_sort(buildings.begin(), buildings.end(),
                   [](const json& a, const json& b) { return a["index"].get<std::size_t>() < b["index"].get<std::size_t>(); });
  std::size_t counts[3] = {0, 0, 0};
  for (const json& b : buildings) {
    const std::string s = b.value("status", "");
    ++counts[s == "ok" ? 0 : s == "refused" ? 1 : 2];
  }
  merged["shard"] = {{"index", 0}, {"count", 1}};
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
    write_glb(options.output, all);
    if (!options.report.empty()) write_file_atomically(options.report, merge_reports(reports).dump(1) + "\n");
    out << "procex merge: " << meshes.size() << " parts, " << all.meshes.size() << " meshes -> " << options.output.string() << "\n";
  } catch (const IoError& e) {
    err << "procex merge: " << e.what() << "\n";
    return kExitUnusableInput;
  }
  return 0;
}

}  // namespace procex
