#include "app/cli/merge_command.h"

#include <algorithm>
#include <map>
#include <ostream>

#include <nlohmann/json.hpp>

#include "app/cli/merge_glb_limit.h"
#include "app/cli/output_paths.h"
#include "app/cli/recipe_session.h"
#include "app/cli/report_merge.h"
#include "app/cli/shard_stamp.h"
#include "base/atomic_file_set.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_crs.h"
#include "core/io/gltf_mesh_spool.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"

namespace procex {
namespace {

using json = nlohmann::ordered_json;

// Buildings read back and written at a time: enough that the writer renders
// them in parallel, few enough to take little memory.
constexpr std::size_t kWindow = 256;

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
    for (const auto& p : meshes)
      if (p.extension() != ".glb") throw IoError(p.string() + ": only .glb shard outputs can be merged", p.string());
    refuse_merge_past_glb_limit(meshes, options.output);
    // Each part is read a building at a time (GlbReader: its JSON indexed,
    // each building's elements and arrays read by their ranges), its
    // buildings set aside on disk (GltfMeshSpool); they are then read back in
    // feature order a window at a time into a streamed .glb: memory holds one
    // part's index and a window of buildings, whatever the parts' size. Each
    // part's placed meshes come along (renumbered, as append_scene does); the
    // writer keeps one of equal ones, so the bytes are those of an unsharded run.
    // Every temporary file goes beside the output, on the disk that is to hold it.
    const std::string folder = folder_beside(options.output);
    GltfMeshSpool spool(folder);
    struct Building {
      std::int64_t feature;
      std::string id;
      GltfMeshSpool::Place at;
    };
    std::vector<Building> buildings;
    std::vector<GltfMeshData> prototypes;
    std::map<std::string, std::string> extras;
    std::vector<std::pair<ShardStamp, std::filesystem::path>> shards;
    for (const auto& p : meshes) {
      const GlbReader part(p);
      const auto stamp = part.extras().find("shard");
      if (stamp == part.extras().end())
        throw IoError(p.string() + ": its scene has no extras.shard, so it is no shard of procex batch: merge joins "
                                   "the .glb parts of one batch run",
                      p.string());
      shards.emplace_back(read_shard_stamp(json::parse(stamp->second), p, "/scenes/0/extras/shard"), p);
      // One run has one CRS; parts that disagree were built with different --crs.
      const auto crs = part.extras().find(kGltfCrsKey);
      const std::string part_crs = crs == part.extras().end() ? "" : crs->second;
      if (shards.size() == 1) {
        if (!part_crs.empty()) extras[kGltfCrsKey] = part_crs;
      } else if (part_crs != (extras.count(kGltfCrsKey) ? extras[kGltfCrsKey] : "")) {
        throw IoError(p.string() + ": its scene's CRS (extras.crs) is not that of " + shards.front().second.string() +
                          ": merge joins the parts of one run, all made in one CRS",
                      p.string());
      }
      for (std::size_t i = 0; i < part.buildings(); ++i) {
        GltfMeshData b = part.building(i);
        for (GltfInstanceData& in : b.instances) in.prototype += prototypes.size();
        buildings.push_back({b.feature, b.building, spool.add(b)});
      }
      prototypes.insert(prototypes.end(), part.prototypes().begin(), part.prototypes().end());
    }
    check_whole(shards);
    if (!shards.empty()) extras["shard"] = to_json(whole_run(shards.front().first)).dump();
    std::stable_sort(buildings.begin(), buildings.end(),
                     [](const Building& a, const Building& b) { return a.feature < b.feature; });
    // A feature in two parts: the same shard given twice, or parts of different splits.
    for (std::size_t i = 1; i < buildings.size(); ++i)
      if (buildings[i].feature >= 0 && buildings[i].feature == buildings[i - 1].feature)
        throw IoError("feature " + std::to_string(buildings[i].feature) + " (" + buildings[i].id +
                          ") is in two parts: give each shard once, all from one run",
                      options.output.string());
    if (!reports.empty() && reports.size() != meshes.size() && !meshes.empty())
      throw IoError(std::to_string(meshes.size()) + " .glb parts but " + std::to_string(reports.size()) +
                        " reports: give the mesh and the report of every shard",
                    options.output.string());
    // Both or neither: the report is read, merged and written beside its
    // target before the mesh, and put in place once the mesh is.
    AtomicFileSet report_file;
    if (!options.report.empty()) {
      MergedReport merged(reports, folder);
      if (!shards.empty() && !merged.shard().empty() && merged.shard() != extras["shard"])
        throw IoError("the reports and the .glb parts come from different runs: give the mesh and the report of "
                      "every shard of one run",
                      options.output.string());
      report_file.add(options.report, merged.pieces());
    }
    GlbStreamWriter glb(options.output, std::move(extras));
    for (std::size_t first = 0; first < buildings.size(); first += kWindow) {
      // The window's buildings, with the placed meshes they show renumbered in order of first use.
      GltfScene window;
      std::map<std::size_t, std::size_t> shown;
      for (std::size_t i = first; i < std::min(buildings.size(), first + kWindow); ++i) {
        GltfMeshData& b = window.meshes.emplace_back(spool.get(buildings[i].at));
        for (GltfInstanceData& in : b.instances) {
          const auto [it, added] = shown.try_emplace(in.prototype, window.prototypes.size());
          if (added) window.prototypes.push_back(prototypes[in.prototype]);
          in.prototype = it->second;
        }
      }
      glb.add({std::move(window)});
    }
    glb.finish();
    report_file.commit();
    out << "procex merge: " << meshes.size() << " parts, " << buildings.size() << " meshes -> " << options.output.string() << "\n";
  } catch (const IoError& e) {
    err << "procex merge: " << e.what() << "\n";
    return kExitUnusableInput;
  }
  return 0;
}

}  // namespace procex
