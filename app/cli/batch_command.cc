#include "app/cli/batch_command.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <ostream>

#include <nlohmann/json.hpp>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "app/cli/feature_binding.h"
#include "app/cli/recipe_session.h"
#include "core/io/atomic_write.h"
#include "core/io/geojson.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"
#include "nodes/support/mesh_export.h"
#include "nodes/support/mesh_summary.h"

namespace procex {
namespace {

struct Building {
  std::size_t index = 0;  // in the file's features array
  std::string id;
  const GeoJsonFeature* feature = nullptr;  // null: the feature could not be read
  std::string status = "ok";                // ok, refused (unreadable feature), failed
  std::string reason;
  std::vector<std::string> warnings;
  MeshSet meshes;                     // dropped once converted for a single .glb
  GltfScene gltf;                     // for a single .glb: converted by the worker, in parallel
  MeshSummary summary;
  double ms = 0;
};

std::string file_name(const std::string& id) {
  std::string out;
  for (unsigned char c : id) out += (std::isalnum(c) || c == '-' || c == '_' || c == '.') ? static_cast<char>(c) : '_';
  return out.empty() || out[0] == '.' ? "_" + out : out;
}

void evaluate_building(const MeshRecipe& recipe, Evaluator& evaluator, bool to_glb, Building& b) {
  const auto start = std::chrono::steady_clock::now();
  Graph graph = recipe.graph;
  Bindings bindings = recipe.bindings;
  EvalOptions options = recipe.options;
  b.warnings = bind_feature(graph, bindings, options, *b.feature);
  options.parallel = false;  // buildings run in parallel already
  const EvalResult r = evaluator.evaluate(graph, bindings, recipe.outputs, options);
  for (const Diagnostic& d : r.diagnostics) {
    if (d.severity == Severity::kWarning) b.warnings.push_back(d.to_string());
    else b.reason += (b.reason.empty() ? "" : "; ") + d.to_string();
  }
  if (!r.ok()) {
    b.status = "failed";
    if (b.reason.empty()) b.reason = "an output is missing";
  } else {
    b.meshes = gather_meshes(r);
    label_parts(b.meshes, *b.feature);
    b.summary = summarize(b.meshes);
    if (to_glb) {
      b.gltf = to_gltf(b.meshes);
      b.meshes = {};
    }
  }
  b.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// A bar redrawn in place on a terminal; otherwise a line every 10 %.
class Progress {
 public:
  Progress(std::ostream& err, std::size_t total, bool enabled)
      : err_(err), total_(total), enabled_(enabled && total > 0), tty_(isatty(STDERR_FILENO) != 0) {}
  void step() {
    const std::size_t done = ++done_;
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    const std::size_t percent = done * 100 / total_;
    if (tty_) {
      if (percent == last_ && done != total_) return;
      const std::size_t filled = percent * 30 / 100;
      err_ << "\r[" << std::string(filled, '#') << std::string(30 - filled, ' ') << "] " << done << "/" << total_
           << (done == total_ ? "\n" : "") << std::flush;
    } else if (percent / 10 != last_ / 10 || done == total_) {
      err_ << "procex batch: " << done << "/" << total_ << " buildings\n";
    }
    last_ = percent;
  }

 private:
  std::ostream& err_;
  std::size_t total_;
  bool enabled_, tty_;
  std::atomic<std::size_t> done_{0};
  std::mutex mutex_;
  std::size_t last_ = 0;
};

nlohmann::ordered_json building_json(const Building& b) {
  nlohmann::ordered_json j;
  j["index"] = b.index;
  j["id"] = b.id;
  j["status"] = b.status;
  j["reason"] = b.reason;
  j["warnings"] = b.warnings;
  const MeshSummary& s = b.summary;
  j["meshes"] = s.meshes;
  j["faces"] = s.faces;
  j["faces_per_tag"] = s.faces_per_tag;
  j["bounds"] = {{"min", {s.min.x, s.min.y, s.min.z}}, {"max", {s.max.x, s.max.y, s.max.z}}};
  j["volume"] = s.volume;
  j["placed"] = s.placed;
  j["ms"] = b.ms;
  return j;
}

bool is_folder_output(const std::filesystem::path& p) {
  const std::string s = p.string();
  return (!s.empty() && s.back() == '/') || std::filesystem::is_directory(p);
}

}  // namespace

bool parse_shard(const std::string& text, std::size_t& shard, std::size_t& shards) {
  std::size_t i = 0, n = 0;
  char slash = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%zu%c%zu%c", &i, &slash, &n, &rest) != 3 || slash != '/' || n == 0 || i >= n)
    return false;
  shard = i, shards = n;
  return true;
}

int run_batch(const BatchCommandOptions& options, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  const bool per_building = is_folder_output(options.output);
  const std::string format = "." + options.format;
  if (per_building ? !is_mesh_file("x" + format) : !is_mesh_file(options.output)) {
    err << "procex batch: " << (per_building ? "--format " + options.format : options.output.string())
        << ": use .obj, .ply or .glb\n";
    return kExitUnusableInput;
  }
  const std::optional<MeshRecipe> recipe = open_mesh_recipe(options.recipe, options.settings, err);
  if (!recipe) return kExitUnusableInput;
  const std::optional<GeoJsonCollection> opened =
      open_footprints(recipe->graph, options.recipe, options.footprints, "batch", err);
  if (!opened) return kExitUnusableInput;
  const GeoJsonCollection& collection = *opened;

  std::vector<Building> buildings;
  for (const GeoJsonFeature& f : collection.features)
    if (f.index % options.shards == options.shard) {
      Building& b = buildings.emplace_back();
      b.index = f.index, b.id = f.id, b.feature = &f;
    }
  for (const GeoJsonFeatureError& e : collection.errors)
    if (e.index % options.shards == options.shard) {
      Building& b = buildings.emplace_back();
      b.index = e.index, b.id = e.id, b.status = "refused", b.reason = e.message;
    }
  std::sort(buildings.begin(), buildings.end(), [](const Building& a, const Building& b) { return a.index < b.index; });

  // Shared by all workers: nodes that do not depend on the building (profiles) run once.
  // Per-building results are never asked for twice, so the cache stays small.
  ResultCache cache(std::size_t{32} << 20);
  const bool one_glb = !per_building && options.output.extension() == ".glb";
  Evaluator evaluator(cache, kEngineSalt);
  Progress progress(err, buildings.size(), options.progress);
  tbb::task_arena arena(options.jobs > 0 ? options.jobs : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, buildings.size(), [&](std::size_t i) {
      if (buildings[i].feature)
        evaluate_building(*recipe, evaluator, one_glb, buildings[i]);
      progress.step();
    });
  });

  cache.clear();  // per-building results are never asked for again: free them before the write's peak
  const auto evaluated = std::chrono::steady_clock::now();
  std::size_t ok = 0, refused = 0, failed = 0;
  MeshSet all;
  GltfScene all_gltf;
  try {
    if (per_building) std::filesystem::create_directories(options.output);
    for (Building& b : buildings) {
      if (b.status == "ok") {
        ++ok;
        if (per_building) write_mesh_set(options.output / (file_name(b.id) + format), b.meshes);
        else if (one_glb) append_scene(all_gltf, std::move(b.gltf));
        else all.parts.insert(all.parts.end(), b.meshes.parts.begin(), b.meshes.parts.end());
        continue;
      }
      ++(b.status == "refused" ? refused : failed);
      err << "procex batch: feature " << b.id << " (index " << b.index << "): " << b.status << ": " << b.reason << "\n";
    }
    if (one_glb) arena.execute([&] { write_glb(options.output, all_gltf); });  // renders buildings in parallel: --jobs holds
    else if (!per_building) write_mesh_set(options.output, all);
    const auto written = std::chrono::steady_clock::now();
    if (!options.report.empty()) {
      nlohmann::ordered_json report;
      report["recipe"] = options.recipe.string();
      report["footprints"] = options.footprints.string();
      report["output"] = options.output.string();
      report["shard"] = {{"index", options.shard}, {"count", options.shards}};
      report["buildings"] = nlohmann::ordered_json::array();
      for (const Building& b : buildings) report["buildings"].push_back(building_json(b));
      auto ms = [](auto from, auto to) { return std::chrono::duration<double, std::milli>(to - from).count(); };
      report["summary"] = {{"buildings", buildings.size()}, {"ok", ok}, {"refused", refused}, {"failed", failed},
                           {"evaluate_ms", ms(start, evaluated)}, {"write_ms", ms(evaluated, written)},
                           {"ms", ms(start, std::chrono::steady_clock::now())}};
      write_file_atomically(options.report, report.dump(1) + "\n");
    }
  } catch (const std::exception& e) {  // IoError, or a folder that cannot be made
    err << "procex batch: " << e.what() << "\n";
    return kExitUnusableInput;
  }
  out << "procex batch: " << buildings.size() << " buildings: " << ok << " ok, " << refused << " refused, " << failed
      << " failed -> " << options.output.string() << "\n";
  return failed > 0 ? kExitEvaluationFailed : 0;
}

}  // namespace procex
