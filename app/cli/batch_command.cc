#include "app/cli/batch_command.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <charconv>
#include <istream>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "app/cli/feature_binding.h"
#include "app/cli/glb_size_estimate.h"
#include "app/cli/ordered_pipeline.h"
#include "app/cli/output_crs.h"
#include "app/cli/output_paths.h"
#include "app/cli/recipe_session.h"
#include "app/cli/report_entries.h"
#include "app/cli/shard_stamp.h"
#include "base/atomic_file_set.h"
#include "base/read_file.h"
#include "core/io/feature_sources.h"
#include "core/io/feature_spool.h"
#include "core/io/footprint_read.h"
#include "core/io/geojson.h"
#include "core/io/gltf_crs.h"
#include "core/io/gltf_write.h"
#include "core/io/io_error.h"
#include "graph/hash.h"
#include "nodes/support/mesh_export.h"
#include "nodes/support/mesh_summary.h"

namespace procex {
namespace {

struct Building {
  std::size_t index = 0;  // in the file's features array
  std::string id;
  std::optional<GeoJsonFeature> feature;    // none: it could not be read (or the building is made)
  std::string status = "ok";                // ok, refused (unreadable feature), failed
  std::string reason;
  std::string file;  // per-building output: its file name in the folder
  std::vector<std::string> warnings;
  MeshSet meshes;                     // dropped once converted for a single .glb
  GltfScene gltf;                     // for a single .glb: converted by the worker, in parallel
  MeshSummary summary;
  double ms = 0;
};

// What identifies a run's inputs in its report, so that merge can tell the
// shards of one run from those of another: the bytes of `files`, and which
// of them are there. The footprints are every file read with them
// (footprint_files): a Shapefile's heights are in its .dbf, its CRS in its
// .prj, its text encoding in its .cpg, and the .shp alone says none of it.
std::string file_hash(const std::vector<std::filesystem::path>& files) {
  Hasher h;
  for (const std::filesystem::path& f : files) {
    std::error_code error;
    if (!std::filesystem::exists(f, error)) {
      h.u64(0);
      continue;
    }
    // A block at a time, each hashed as bytes of its own: a million
    // footprints are 200 MB of GeoJSON, which held whole beside the features
    // read from it set the batch's peak.
    const std::unique_ptr<std::istream> in = open_file_stream(f, kMaxDataFileBytes);
    h.u64(std::filesystem::file_size(f) + 1);
    std::vector<char> block(std::size_t{1} << 20);
    while (in->read(block.data(), static_cast<std::streamsize>(block.size())) || in->gcount() > 0)
      h.bytes(block.data(), static_cast<std::size_t>(in->gcount()));
    if (in->bad()) throw IoError("cannot read '" + f.string() + "': reading failed part-way", f.string());
  }
  return h.result().hex();
}

// The files the buildings' plans come from: the footprints, and the streets
// that decide which of their edges face one.
std::vector<std::filesystem::path> plan_files(const BatchCommandOptions& options) {
  std::vector<std::filesystem::path> files = footprint_files(options.footprints);
  if (!options.streets.empty())
    for (const std::filesystem::path& f : footprint_files(options.streets)) files.push_back(f);
  return files;
}

// Per-building file names: the id with characters other than [A-Za-z0-9._-]
// as '_', cut to a length every file system takes, and made unique (ignoring
// case, for file systems that fold it) with the feature's index after a '~',
// which no cleaned id contains: ids that collide once cleaned ("a/b" and
// "a_b", two ids in another script), repeat, or are too long for a file name
// never overwrite each other. Named in input order, as buildings stream out.
class FileNames {
 public:
  explicit FileNames(std::string format) : format_(std::move(format)) {}
  std::string operator()(const Building& b) {
    constexpr std::size_t kMaxStem = 100;
    std::string stem;
    for (unsigned char c : b.id) stem += (std::isalnum(c) || c == '-' || c == '_' || c == '.') ? static_cast<char>(c) : '_';
    if (stem.empty() || stem[0] == '.') stem.insert(0, "_");
    const bool cut = stem.size() > kMaxStem;
    stem.resize(std::min(stem.size(), kMaxStem));
    std::string key = stem;
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (cut || !used_.insert(key).second) stem += "~" + std::to_string(b.index);
    return stem + format_;
  }

 private:
  std::string format_;
  std::set<std::string> used_;
};

// What a batch into one file holds until it is written, counted as buildings
// finish: a batch over its budget stops early and writes nothing, whatever the
// order its buildings ran in, instead of running out of memory. (Per-building
// files and a single .glb stream out as buildings finish: no budget.)
struct BatchBudget {
  std::size_t max_faces, max_placed;
  std::atomic<std::size_t> faces{0}, placed{0};
  std::atomic<bool> exceeded{false};

  void add(const MeshSet& meshes) {
    std::size_t f = 0, p = 0;
    for (const TaggedMesh& part : meshes.parts) {
      f += part.mesh->n_faces() + part.placed.placed_faces;
      p += part.placed.instances.size();
    }
    if (faces += f; faces > max_faces) exceeded = true;
    if (placed += p; placed > max_placed) exceeded = true;
  }
};

// `prototypes`: the batch's placed meshes in glTF form (to_glb).
void evaluate_building(const MeshRecipe& recipe, Evaluator& evaluator, bool to_glb,
                       const std::shared_ptr<GltfPrototypeMemo>& prototypes, BatchBudget& budget, Building& b) {
  const auto start = std::chrono::steady_clock::now();
  FeatureEvaluation e = evaluate_feature(recipe, evaluator, *b.feature, /*parallel=*/false);  // buildings are parallel
  b.feature.reset();
  b.status = e.status();
  b.warnings = e.warnings();
  b.reason = e.reason();
  if (!e.binding_problems.empty()) return;
  if (e.ok) {
    b.meshes = std::move(e.meshes);
    budget.add(b.meshes);
    if (budget.exceeded) return;  // the batch is refused: free nothing more
    b.summary = summarize(b.meshes);
    if (to_glb) {
      b.gltf = to_gltf(b.meshes, prototypes);
      b.meshes = {};
    }
  }
  b.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The .glb bytes each building made for a .glb takes (0: refused or failed),
// measured by a writer of their own that is never finished.
std::vector<std::uint64_t> glb_bytes_each(std::vector<Building>& buildings, const std::filesystem::path& output) {
  GlbStreamWriter measure(output, {}, std::numeric_limits<std::uint64_t>::max());
  std::vector<std::uint64_t> bytes;
  for (Building& b : buildings) {
    const std::uint64_t before = measure.bytes();
    if (b.status == "ok") {
      std::vector<GltfScene> one(1);
      one[0] = std::move(b.gltf);
      measure.add(std::move(one));
    }
    bytes.push_back(measure.bytes() - before);
  }
  return bytes;
}

// A bar redrawn in place on a terminal; otherwise a line every 10 %.
class Progress {
 public:
  Progress(std::ostream& err, std::size_t total, bool enabled)
      : err_(err), total_(total), enabled_(enabled && total > 0), tty_(isatty(STDERR_FILENO) != 0) {}
  // A building written (called one at a time, as the batch's other messages are).
  void step() {
    const std::size_t done = ++done_;
    if (!enabled_) return;
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
  std::size_t done_ = 0, last_ = 0;
};

nlohmann::ordered_json building_json(const Building& b) {
  nlohmann::ordered_json j;
  j["index"] = b.index;
  j["id"] = b.id;
  j["status"] = b.status;
  j["reason"] = b.reason;
  if (!b.file.empty()) j["file"] = b.file;
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

// Where the footprints' spool goes: beside the output, on the disk that is to
// hold it (the output's folder, or the nearest folder above it that exists
// yet: nothing is made before the footprints are read).
std::string spool_folder(const std::filesystem::path& output, bool per_building) {
  std::filesystem::path folder = per_building ? output : output.parent_path();
  std::error_code ec;
  while (!folder.empty() && !std::filesystem::is_directory(folder, ec)) folder = folder.parent_path();
  return folder.empty() ? "." : folder.string();
}

}  // namespace

bool parse_shard(const std::string& text, std::size_t& shard, std::size_t& shards) {
  // Digits only: sscanf's %zu takes "-2" (and wraps it) and overflows silently.
  auto number = [](std::string_view digits, std::size_t& out) {
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
    return !digits.empty() && ec == std::errc() && end == digits.data() + digits.size();
  };
  const std::size_t slash = text.find('/');
  std::size_t i = 0, n = 0;
  if (slash == std::string::npos || !number(std::string_view(text).substr(0, slash), i) ||
      !number(std::string_view(text).substr(slash + 1), n) || n == 0 || i >= n)
    return false;
  shard = i, shards = n;
  return true;
}

int run_batch(const BatchCommandOptions& options, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  const bool per_building = is_folder_output(options.output);
  const std::string format = "." + options.format;
  const std::filesystem::path kind = per_building ? std::filesystem::path("x" + format) : options.output;
  if (!is_mesh_file(kind) && !is_gis_file(kind)) {
    err << "procex batch: " << (per_building ? "--format " + options.format : options.output.string())
        << ": use .obj, .ply, .glb, .gpkg or .json (CityJSON)\n";
    return kExitUnusableInput;
  }
  if (const auto clash = output_clash({options.recipe, options.footprints, options.streets},
                                      {per_building ? std::filesystem::path() : options.output, options.report})) {
    err << "procex batch: " << *clash << "\n";
    return kExitUnusableInput;
  }
  std::optional<MeshRecipe> recipe = open_mesh_recipe(options.recipe, options.settings, options.allowed_paths, err, {},
                                                          options.budget);
  if (!recipe) return kExitUnusableInput;
  recipe->options.lod = options.lod;
  recipe->options.pin_files_for_a_batch();  // the same files for every building
  FootprintReadOptions read;
  read.crs = options.export_options.crs, read.target_crs = options.target_crs, read.layer = options.layer;
  read.streets = options.streets, read.streets_layer = options.streets_layer;
  // The footprints wait on disk beside the output, read back a window at a
  // time: a million of them in memory would be most of the batch's peak. So
  // do the report's entries (and a .glb's parts, GlbStreamWriter): every
  // temporary file on the disk that is to hold the output, none in /tmp.
  std::optional<FeatureSpool> footprints;
  std::optional<ReportEntries> entries;
  try {
    footprints.emplace(spool_folder(options.output, per_building));
    entries.emplace(spool_folder(options.output, per_building));
  } catch (const IoError& e) {
    err << "procex batch: " << e.what() << "\n";
    return kExitUnusableInput;
  }
  const std::optional<GeoJsonCollection> opened =
      open_footprints(recipe->graph, options.recipe, options.footprints, read, "batch", err, &*footprints);
  if (!opened) return kExitUnusableInput;
  const GeoJsonCollection& collection = *opened;
  ExportOptions export_options = options.export_options;
  if (const auto problem = settle_output_crs(kind, &collection, export_options)) {
    err << "procex batch: " << options.output.string() << ": " << *problem << "\n";
    return kExitUnusableInput;
  }

  // The shard's features, readable or not, in input order: each building's
  // record is made from these as it is read back, so records for every
  // building are never held at once.
  const std::vector<FeatureSource> sources =
      feature_sources(*footprints, collection.errors, options.shard, options.shards);

  // Shared by all workers: nodes that do not depend on the building (profiles) run once.
  // Per-building results are never asked for twice, so the cache stays small.
  ResultCache cache(std::size_t{32} << 20);
  const bool one_glb = !per_building && options.output.extension() == ".glb";
  Evaluator evaluator(cache, kEngineSalt);
  const auto prototypes = std::make_shared<GltfPrototypeMemo>();
  Progress progress(err, sources.size(), options.progress);
  constexpr std::size_t kUnlimited = static_cast<std::size_t>(-1);
  const bool streamed = per_building || one_glb;
  BatchBudget budget{streamed ? kUnlimited : options.max_faces, streamed ? kUnlimited : options.max_placed};
  tbb::task_arena arena(options.jobs > 0 ? options.jobs : tbb::task_arena::automatic);
  std::size_t ok = 0, refused = 0, failed = 0;
  ShardStamp stamp{options.shard, options.shards, {}, {}};  // its hashes read when a report or a .glb is written
  std::chrono::steady_clock::time_point evaluated = start;
  auto report = [&](std::chrono::steady_clock::time_point written) {
    nlohmann::ordered_json j;
    j["recipe"] = options.recipe.string();
    j["footprints"] = options.footprints.string();
    j["output"] = options.output.string();
    j["shard"] = to_json(stamp);
    j["buildings"] = nlohmann::ordered_json::array();
    auto ms = [](auto from, auto to) { return std::chrono::duration<double, std::milli>(to - from).count(); };
    j["summary"] = {{"buildings", sources.size()}, {"ok", ok}, {"refused", refused}, {"failed", failed},
                    {"evaluate_ms", ms(start, evaluated)}, {"write_ms", ms(evaluated, written)},
                    {"ms", ms(start, std::chrono::steady_clock::now())}};
    return entries->report(j);
  };
  MeshSet all;
  std::optional<GlbStreamWriter> glb;
  FileNames file_name(format);
  std::size_t made = 0;  // buildings handed to the output so far (ok or not)
  try {
    if (one_glb) {
      // Whether one .glb can hold the batch, from a sample made ahead: a batch
      // that cannot is refused before its buildings are made, not when its
      // file passes the limit, hours in.
      const std::vector<std::size_t> at = glb_size_sample(sources.size());
      std::vector<Building> sample(at.size());
      for (std::size_t i = 0; i < at.size(); ++i)
        if (const FeatureSource& from = sources[at[i]]; !from.error) sample[i].feature = footprints->at(from.spooled);
        else sample[i].status = "refused";
      arena.execute([&] {
        tbb::parallel_for(std::size_t{0}, sample.size(), [&](std::size_t i) {
          if (sample[i].feature) evaluate_building(*recipe, evaluator, true, prototypes, budget, sample[i]);
        });
      });
      if (const GlbSizeEstimate e = estimate_glb_size(glb_bytes_each(sample, options.output), sources.size());
          e.at_least > static_cast<double>(options.glb_max_bytes)) {
        err << "procex batch: refused: " << glb_too_large_message(options.output, e, options.glb_max_bytes) << "\n";
        return kExitUnusableInput;
      }
    }
    // Meshes and report both or neither: the report is staged (beside its
    // target) before any mesh is written, so a report that cannot be written
    // stops the run before any mesh is replaced; it is put in place with its
    // final numbers once the meshes are.
    AtomicFileSet report_file;
    if (!options.report.empty() || one_glb)
      stamp.recipe = file_hash({options.recipe}), stamp.footprints = file_hash(plan_files(options));
    if (!options.report.empty()) report_file.add(options.report, report(start));
    if (one_glb) {
      GltfScene head;
      head.extras["shard"] = to_json(stamp).dump();  // merge reads it from the .glb alone too
      set_gltf_crs(head, export_options.crs, options.output);
      glb.emplace(options.output, std::move(head.extras), options.glb_max_bytes);
    }
    if (per_building) std::filesystem::create_directories(options.output);
    // Buildings are read back from the spool in input order (and named, for
    // per-building files), evaluated and written to their own files in
    // parallel, and leave in input order: into the report, and into the
    // single .glb's temporary files (a group at a time, rendered in parallel)
    // or what another single output keeps. Their meshes are freed as they
    // leave, so the meshes in memory at once are those of the `ahead`
    // buildings between read and left, however many the batch has.
    const std::size_t jobs = static_cast<std::size_t>(std::max(1, arena.max_concurrency()));
    const std::size_t glb_group = 16 * jobs;
    std::vector<GltfScene> group;
    const auto make = [&](std::size_t i) {
      const FeatureSource& from = sources[i];
      Building b;
      b.index = from.index;
      if (!from.error) b.feature = footprints->at(from.spooled), b.id = b.feature->id;
      else b.id = from.error->id, b.status = "refused", b.reason = from.error->message;
      if (per_building) b.file = file_name(b);
      return b;
    };
    const auto work = [&](Building& b) {
      if (!b.feature || budget.exceeded) return;
      evaluate_building(*recipe, evaluator, one_glb, prototypes, budget, b);
      if (per_building && b.status == "ok")
        write_mesh_set(options.output / b.file, std::exchange(b.meshes, {}), export_options);
    };
    const auto finish = [&](Building& b) {
      if (budget.exceeded) return;
      progress.step();
      entries->add(ReportEntries::text(building_json(b)));  // made as it leaves
      ++made;
      if (b.status != "ok") {
        ++(b.status == "refused" ? refused : failed);
        err << "procex batch: feature " << b.id << " (index " << b.index << "): " << b.status << ": " << b.reason
            << "\n";
        return;
      }
      ++ok;
      if (one_glb) {
        group.push_back(std::move(b.gltf));
        if (group.size() == glb_group) glb->add(std::exchange(group, {}));
      } else if (!per_building) {
        all.parts.insert(all.parts.end(), b.meshes.parts.begin(), b.meshes.parts.end());
      }
    };
    arena.execute([&] {
      run_in_order<Building>(sources.size(), 64 * jobs, make, work, finish, [&] { return budget.exceeded.load(); });
      if (one_glb && !budget.exceeded) glb->add(std::move(group));  // renders in parallel: --jobs holds
    });
    if (budget.exceeded) {
      err << "procex batch: refused: the buildings would hold more than " << options.max_faces << " faces or "
          << options.max_placed << " placed meshes (" << budget.faces << " faces, " << budget.placed
          << " placed meshes when it stopped), more than one run should hold in memory; nothing written. Split the "
             "batch with --shard i/N and join the parts with procex merge, or raise --max-faces / --max-placed\n";
      return kExitUnusableInput;
    }
    cache.clear();  // per-building results are never asked for again: free them before the write's peak
    evaluated = std::chrono::steady_clock::now();
    if (one_glb) glb->finish();
    else if (!per_building) write_mesh_set(options.output, all, export_options);
    all = {};
    if (!options.report.empty()) {
      report_file.add(options.report, report(std::chrono::steady_clock::now()));
      report_file.commit();
    }
  } catch (const GlbTooLarge& e) {  // the sample above judged the batch to fit, and it did not
    err << "procex batch: refused: " << e.what() << " with " << made << " of its " << sources.size()
        << " buildings made; nothing written. "
        << glb_too_large_advice(static_cast<double>(glb->bytes()) * static_cast<double>(sources.size()) /
                                    static_cast<double>(std::max<std::size_t>(made, 1)),
                                options.glb_max_bytes)
        << "\n";
    return kExitUnusableInput;
  } catch (const std::exception& e) {  // IoError, or a folder that cannot be made
    err << "procex batch: " << e.what() << "\n";
    return kExitUnusableInput;
  }
  out << "procex batch: " << sources.size() << " buildings: " << ok << " ok, " << refused << " refused, " << failed
      << " failed -> " << options.output.string() << "\n";
  // Nothing produced is no success, even when every building was only refused.
  return failed > 0 || ok == 0 ? kExitEvaluationFailed : 0;
}

}  // namespace procex
