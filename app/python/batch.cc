#include "app/python/batch.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <pybind11/stl.h>

#include "app/cli/feature_binding.h"
#include "app/python/errors.h"
#include "app/python/footprint_input.h"
#include "app/python/mesh_arrays.h"
#include "app/python/recipe.h"
#include "base/confined_path_memo.h"

namespace py = pybind11;

namespace procex::python {
namespace {

struct Building {
  std::size_t index = 0;  // in the footprints given
  std::string id;
  std::string status = "ok";  // ok, refused (the feature cannot be read), failed (evaluation)
  std::string reason;
  std::vector<std::string> warnings;
  WrappedMeshes meshes;  // wrapped by the worker that evaluated it
  py::object wrapped;    // their list, made with the GIL held once the workers are done
  py::object feature;    // the feature as evaluated (a dict), None when it could not be read
};

// What the workers share with the thread that holds the GIL.
struct Progress {
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t done = 0;
  bool finished = false;
  std::atomic<bool> stop{false};
};

void evaluate(const MeshRecipe& recipe, Evaluator& evaluator, const GeoJsonFeature& f, PlaceableCache& placeables,
              Building& b) {
  FeatureEvaluation e = evaluate_feature(recipe, evaluator, f, /*parallel=*/false);  // buildings are parallel
  b.warnings = e.warnings();
  b.reason = e.reason();
  if (e.ok) b.meshes = wrap_all(std::move(e.meshes), placeables);
  else b.status = e.binding_problems.empty() ? "failed" : "refused";
}

py::list batch(const std::shared_ptr<Recipe>& recipe, py::handle footprints, int jobs, py::handle progress,
               py::handle attributes, py::handle streets) {
  MeshRecipe r = recipe->with(attributes);
  r.options.resolved_paths = std::make_shared<ConfinedPathMemo>();  // the same files for every building
  if (const Status s = check_footprint_input(r.graph, recipe->file()); !s) raise(ErrorKind::Recipe, s.message());
  GeoJsonCollection collection = collection_from_python(footprints);
  add_streets(collection, streets);
  add_edge_labels(r.graph, collection);

  std::vector<Building> buildings(collection.features.size() + collection.errors.size());
  std::vector<const GeoJsonFeature*> feature_of(buildings.size(), nullptr);
  for (const GeoJsonFeature& f : collection.features) {
    buildings[f.index].index = f.index, buildings[f.index].id = f.id;
    feature_of[f.index] = &f;
  }
  for (const GeoJsonFeatureError& e : collection.errors)
    buildings[e.index] = Building{e.index, e.id, "refused", e.message, {}, {}, {}, py::none()};

  // Per-building results are never asked for twice: a small cache of its own,
  // where what does not depend on the building (profiles) is computed once.
  ResultCache cache(std::size_t{32} << 20);
  Evaluator evaluator(cache, kEngineSalt);
  PlaceableCache placeables;  // the window every building places is wrapped once
  Progress shared;
  tbb::task_arena arena(jobs > 0 ? jobs : tbb::task_arena::automatic);
  std::thread worker([&] {
    arena.execute([&] {
      tbb::parallel_for(std::size_t{0}, buildings.size(), [&](std::size_t i) {
        if (feature_of[i] && !shared.stop) evaluate(r, evaluator, *feature_of[i], placeables, buildings[i]);
        std::lock_guard lock(shared.mutex);
        ++shared.done;
        shared.changed.notify_all();
      });
    });
    std::lock_guard lock(shared.mutex);
    shared.finished = true;
    shared.changed.notify_all();
  });

  // The GIL is released except to report progress and look for Ctrl+C; an
  // exception from either stops the buildings not yet started.
  std::size_t reported = 0;
  try {
    for (;;) {
      std::size_t done = 0;
      bool finished = false;
      {
        py::gil_scoped_release release;
        std::unique_lock lock(shared.mutex);
        shared.changed.wait_for(lock, std::chrono::milliseconds(100),
                                [&] { return shared.finished || shared.done != reported; });
        done = shared.done, finished = shared.finished;
      }
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!progress.is_none() && done != reported) progress(done, buildings.size());
      reported = done;
      if (finished) break;
    }
  } catch (...) {
    shared.stop = true;
    r.options.cancel.cancel();
    {
      py::gil_scoped_release release;
      worker.join();
    }
    throw;
  }
  worker.join();

  py::list out(buildings.size());
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    buildings[i].wrapped = to_list(buildings[i].meshes);
    buildings[i].feature = feature_of[i] ? py::object(feature_to_python(*feature_of[i])) : py::object(py::none());
    out[i] = py::cast(std::move(buildings[i]));
  }
  return out;
}

}  // namespace

void bind_batch(py::module_& m) {
  py::class_<Building>(m, "Building", "One footprint of a batch: its id, status and meshes.")
      .def_readonly("index", &Building::index, "Its position among the footprints given.")
      .def_readonly("id", &Building::id, "The feature's id (its index as text when it has none).")
      .def_readonly("status", &Building::status,
                    "ok; refused (the feature cannot be read); failed (a node failed: see reason).")
      .def_readonly("reason", &Building::reason, "Why it was refused or failed, as procex batch reports it.")
      .def_readonly("warnings", &Building::warnings)
      .def_readonly("meshes", &Building::wrapped, "Its meshes (Mesh), named by building id; empty unless ok.")
      .def_readonly("feature", &Building::feature,
                    "The feature as it was evaluated, a GeoJSON Feature dict: its id, its properties (with party_edges "
                    "and street_edges when the recipe reads them and procex found them), its outline in the batch's "
                    "frame (a file's coordinates projected as procex batch projects them). "
                    "Recipe.evaluate(footprint=feature) makes the same meshes again. None when it could not be read.")
      .def("__repr__", [](const Building& b) {
        return "<procex.Building " + b.id + " " + b.status + ", " + std::to_string(py::len(b.wrapped)) + " meshes>";
      });
  m.def("batch", &batch, py::arg("recipe"), py::arg("footprints"), py::arg("jobs") = 0,
        py::arg("progress") = py::none(), py::arg("attributes") = py::none(), py::arg("streets") = py::none(),
        "Evaluates the recipe once per footprint, in parallel, as procex batch does: each feature is bound to the "
        "graph input footprint, its id to building_id, its properties to the parameters of the same name. "
        "footprints: a footprint file's path (GeoJSON, Shapefile, GeoPackage, FlatGeobuf or OSM, longitude/latitude projected "
        "as procex batch projects it), a FeatureCollection dict, or a sequence of features or of loops. streets: as "
        "procex batch --streets, a second file whose LineStrings are streets (brought into the footprints' frame), or a "
        "FeatureCollection dict of them in the footprints' coordinates; a recipe that reads street_edges gets each "
        "feature's edges facing one, as it does from the footprint file's own lines. jobs: worker "
        "threads (0: one per core). progress(done, total) is called from this thread as buildings finish. The GIL "
        "is released while the buildings are evaluated; an exception in progress (or Ctrl+C) stops the rest. "
        "Returns one Building per footprint, in order: a building that fails does not stop the others.");
}

}  // namespace procex::python
