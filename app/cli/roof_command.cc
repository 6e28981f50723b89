#include "app/cli/roof_command.h"

#include <algorithm>
#include <chrono>
#include <new>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "app/cli/output_paths.h"
#include "app/cli/report_text.h"
#include "core/geom/error.h"
#include "core/geom/prepare.h"
#include "base/atomic_file_set.h"
#include "core/io/footprint_read.h"
#include "core/io/io_error.h"
#include "core/io/mesh_write.h"
#include "core/mesh/mesh.h"
#include "core/mesh/validate.h"
#include "core/sweep/sweep.h"
#include "nodes/support/errors.h"

namespace procex {
namespace {

enum class Status { Ok, Refused, Failed };

const char* status_name(Status s) {
  switch (s) {
    case Status::Ok: return "ok";
    case Status::Refused: return "refused";
    case Status::Failed: return "failed";
  }
  return "?";
}

struct FeatureResult {
  std::size_t index = 0;  // in the file's "features" array
  std::string id;
  const GeoJsonFeature* source = nullptr;  // null when the feature could not be read
  Status status = Status::Ok;
  std::string reason;
  std::vector<std::string> notes;  // repairs and fallbacks, one line each
  Mesh mesh;
  bool validated = false;
  ValidationReport validation;
  double max_height = 0.0;
  // The clustering scale the roof closed at and how many were tried before
  // (Surface::tolerance_relative, retries): 0 and 0 where no roof was made.
  double clustering_scale = 0.0;
  int retries = 0;
  double ms = 0.0;           // prepare + sweep + mesh
  double validate_ms = 0.0;
};

double elapsed_ms(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since).count();
}

std::string first_problems(const ValidationReport& v) {
  constexpr std::size_t kShown = 3;
  std::string s = "mesh does not validate:";
  for (std::size_t i = 0; i < std::min(kShown, v.problems.size()); ++i) s += (i ? "; " : " ") + v.problems[i];
  if (v.problems.size() > kShown) s += "; ... (" + std::to_string(v.problems.size()) + " problems)";
  if (v.problems.empty()) s += " (no problem lines given)";
  return s;
}

// Every exception is caught here: one bad feature never stops the others.
void extrude(const GeoJsonFeature& feature, const RoofOptions& options, FeatureResult& r) {
  const auto start = std::chrono::steady_clock::now();
  try {
    if (!options.angles_property.empty() && feature.edge_angles.empty())
      r.notes.push_back("no property '" + options.angles_property + "': every edge at " +
                        std::to_string(options.angle_deg) + " degrees");
    PreparedFootprint prepared = prepare_footprint(to_footprint(feature, options.angle_deg));
    r.notes.insert(r.notes.end(), prepared.notes.begin(), prepared.notes.end());
    SweepOptions sweep_options;
    sweep_options.max_height = options.max_height;
    sweep_options.budget = with_settings(sweep_options.budget, options.budget);
    const Surface roof = sweep(prepared.footprint, sweep_options);
    r.mesh = build_mesh(roof);
    r.clustering_scale = roof.tolerance_relative, r.retries = roof.retries;
    r.ms = elapsed_ms(start);
    for (const auto v : r.mesh.vertices()) r.max_height = std::max(r.max_height, r.mesh.point(v)[2]);

    const auto validate_start = std::chrono::steady_clock::now();
    r.validation = validate(r.mesh, roof_validation(roof));
    r.validated = true;
    r.validate_ms = elapsed_ms(validate_start);
    if (!r.validation.ok()) r.status = Status::Failed, r.reason = first_problems(r.validation);
  } catch (const InputError& e) {
    r.status = Status::Refused, r.reason = describe(e);
  } catch (const SweepError& e) {
    r.status = Status::Failed, r.reason = describe(e);  // its message names the sweep
  } catch (const MeshError& e) {
    r.status = Status::Failed, r.reason = std::string("mesh: ") + e.what();
  } catch (const std::bad_alloc&) {
    r.status = Status::Failed, r.reason = "ran out of memory sweeping this footprint; run fewer --jobs";
  } catch (const std::exception& e) {
    r.status = Status::Failed, r.reason = std::string("internal error: ") + e.what();
  }
  if (r.ms == 0.0) r.ms = elapsed_ms(start);
}

nlohmann::ordered_json feature_json(const FeatureResult& r) {
  nlohmann::ordered_json j;
  j["id"] = r.id;
  j["index"] = r.index;
  j["status"] = status_name(r.status);
  j["reason"] = r.reason;
  j["notes"] = r.notes;
  const bool has_mesh = r.mesh.n_vertices() > 0;
  j["vertices"] = r.mesh.n_vertices();
  j["faces"] = r.mesh.n_faces();
  j["volume"] = r.validated ? nlohmann::ordered_json(r.validation.volume) : nlohmann::ordered_json();
  j["max_height"] = has_mesh ? nlohmann::ordered_json(r.max_height) : nlohmann::ordered_json();
  j["clustering_scale"] = has_mesh ? nlohmann::ordered_json(r.clustering_scale) : nlohmann::ordered_json();
  j["retries"] = r.retries;
  j["ms"] = r.ms;
  if (r.validated) {
    const ValidationReport& v = r.validation;
    j["validation"] = {{"ok", v.ok()},
                       {"closed", v.closed},
                       {"manifold", v.manifold},
                       {"oriented", v.oriented},
                       {"planar", v.planar},
                       {"self_intersection_free", v.self_intersection_free},
                       {"max_planarity_error", v.max_planarity_error},
                       {"tolerance", v.tolerance},
                       {"problems", v.problems},
                       {"ms", r.validate_ms}};
  } else {
    j["validation"] = nullptr;
  }
  return j;
}

}  // namespace

int run_roof(const RoofOptions& options, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  if (const auto clash = output_clash({options.input}, {options.output, options.report})) {
    err << "procex roof: " << *clash << "\n";
    return kExitUnusableFile;
  }
  GeoJsonCollection collection;
  try {
    FootprintReadOptions read;
    read.geojson = {options.angles_property, /*require_angles=*/false};
    read.crs = options.crs, read.target_crs = options.target_crs, read.layer = options.layer;
    collection = read_footprints(options.input, read);
  } catch (const IoError& e) {
    err << "procex roof: " << e.what() << "\n";
    return kExitUnusableFile;
  }

  std::vector<FeatureResult> results;
  results.reserve(collection.features.size() + collection.errors.size());
  for (const GeoJsonFeature& f : collection.features) {
    FeatureResult& r = results.emplace_back();
    r.index = f.index, r.id = f.id, r.source = &f;
  }
  for (const GeoJsonFeatureError& e : collection.errors) {
    FeatureResult& r = results.emplace_back();
    r.index = e.index, r.id = e.id, r.status = Status::Refused, r.reason = e.message;
  }
  // Unreadable features are refused in place: the report keeps the file's order.
  std::sort(results.begin(), results.end(), [](const auto& a, const auto& b) { return a.index < b.index; });

  tbb::task_arena arena(options.jobs > 0 ? options.jobs : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, results.size(), [&](std::size_t i) {
      if (results[i].source) extrude(*results[i].source, options, results[i]);
    });
  });

  std::size_t counts[3] = {0, 0, 0};
  std::vector<NamedMesh> meshes;
  for (const FeatureResult& r : results) {
    ++counts[static_cast<int>(r.status)];
    if (r.status == Status::Ok) meshes.push_back({r.id, &r.mesh});
    else err << "procex roof: feature " << r.id << " (index " << r.index << "): " << status_name(r.status) << ": "
             << r.reason << "\n";
  }

  nlohmann::ordered_json report;
  report["input"] = options.input.string();
  report["output"] = options.output.string();
  report["options"] = {{"angle", options.angle_deg},
                       {"angles_property", options.angles_property},
                       {"max_height", options.max_height ? nlohmann::ordered_json(*options.max_height)
                                                         : nlohmann::ordered_json()}};
  report["features"] = nlohmann::ordered_json::array();
  for (const FeatureResult& r : results) report["features"].push_back(feature_json(r));
  report["summary"] = {{"features", results.size()},
                       {"ok", counts[static_cast<int>(Status::Ok)]},
                       {"refused", counts[static_cast<int>(Status::Refused)]},
                       {"failed", counts[static_cast<int>(Status::Failed)]},
                       {"ms", elapsed_ms(start)}};
  try {
    // Both or neither: the report is written (beside its target) before the
    // mesh, and put in place only once the mesh is.
    AtomicFileSet report_file;
    report_file.add(options.report, report_text(report));
    write_mesh_file(options.output, meshes);
    report_file.commit();
  } catch (const IoError& e) {
    err << "procex roof: " << e.what() << "\n";
    return kExitUnusableFile;
  }

  const std::size_t failed = counts[static_cast<int>(Status::Failed)];
  out << "procex roof: " << results.size() << " features: " << counts[0] << " ok, " << counts[1] << " refused, "
      << failed << " failed -> " << options.output.string() << ", " << options.report.string() << "\n";
  // Nothing produced is no success, even when every feature was only refused.
  return failed > 0 || counts[0] == 0 ? kExitFeatureFailed : 0;
}

}  // namespace procex
