#include "app/python/batch.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>
#include <pybind11/stl.h>

#include "app/cli/feature_binding.h"
#include "app/cli/ordered_pipeline.h"
#include "app/python/errors.h"
#include "app/python/footprint_input.h"
#include "app/python/mesh_arrays.h"
#include "app/python/recipe.h"
#include "core/io/feature_sources.h"
#include "core/io/feature_spool.h"
#include "core/io/footprint_read.h"
#include "core/io/io_error.h"

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
  b.status = e.status();
  b.warnings = e.warnings();
  b.reason = e.reason();
  if (e.ok) b.meshes = wrap_all(std::move(e.meshes), placeables);
}

py::list batch(const std::shared_ptr<Recipe>& recipe, py::handle footprints, int jobs, py::handle progress,
               py::handle attributes, py::handle streets) {
  MeshRecipe r = recipe->with(attributes);
  r.options.pin_files_for_a_batch();  // the same files for every building
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

// procex.batch_iter: the buildings handed over one at a time, in feature
// order, so that a city is batched in bounded memory (batch() holds every
// building's meshes, 16.5 KB a city building). The footprints wait in a
// FeatureSpool (unnamed temporary file: it goes with the spool, or the
// process) as procex batch keeps them; an OrderedPipeline reads them back in
// order and evaluates them in parallel, going on past a slow building while
// the caller waits for it. It holds at most 64 buildings a job ahead of the
// one the caller waits for and 64 a job evaluated and not taken, as procex
// batch holds (about 2 MB a job of city buildings): with 4 a job, one
// intricate building among houses (150 times their time) stalled the others
// as windows did (BENCHMARKS). Its threads never touch a Python object.
class BatchStream {
 public:
  BatchStream(std::shared_ptr<Recipe> recipe, py::handle footprints, int jobs, py::handle attributes,
              py::handle streets)
      : source_recipe_(std::move(recipe)),
        recipe_(source_recipe_->with(attributes)),
        arena_(jobs > 0 ? jobs : tbb::task_arena::automatic) {
    recipe_.options.pin_files_for_a_batch();
    if (const Status s = check_footprint_input(recipe_.graph, source_recipe_->file()); !s)
      raise(ErrorKind::Recipe, s.message());
    const std::string temp = py::str(py::module_::import("tempfile").attr("gettempdir")());
    GeoJsonCollection collection;
    try {
      spool_.emplace(temp);
      if (py::isinstance<py::str>(footprints) || py::hasattr(footprints, "__fspath__")) {
        const std::string path = py::str(py::module_::import("os").attr("fspath")(footprints));
        collection = read_footprints(path, {}, *spool_);  // as batch() reads it, into the spool
      } else {
        collection = collection_from_python(footprints);  // in Python's memory already
        for (GeoJsonFeature& f : collection.features) spool_->add(std::move(f));
        collection.features.clear();
      }
      add_streets(collection, streets);
      add_edge_labels(recipe_.graph, *spool_, collection.lines);
    } catch (const IoError& e) {
      raise(ErrorKind::Footprint, e.what());
    }
    errors_ = std::move(collection.errors);
    sources_ = feature_sources(*spool_, errors_);
    const std::size_t ahead = 64 * static_cast<std::size_t>(std::max(1, arena_.max_concurrency()));
    pipeline_.emplace(
        sources_.size(), ahead, arena_, [this](std::size_t i) { return pending(i); },
        [this](Pending& p) {
          if (p.feature) evaluate(recipe_, evaluator_, *p.feature, placeables_, p.building);
        },
        "procex-batch");  // what top -H (and a test) sees of it
  }
  ~BatchStream() { close(); }

  std::size_t size() const { return sources_.size(); }

  // The next building (with the GIL); StopIteration after the last or once closed.
  py::object next() {
    Pending p;
    for (;;) {
      Pipeline::Next n = Pipeline::Next::kEnd;
      try {
        py::gil_scoped_release release;
        n = pipeline_->next(p, std::chrono::milliseconds(100));
      } catch (const IoError& e) {  // the spool could not be read back
        close();
        raise(ErrorKind::Footprint, e.what());
      } catch (...) {
        close();
        throw;
      }
      if (n == Pipeline::Next::kItem) break;
      if (n == Pipeline::Next::kEnd) {
        close();
        throw py::stop_iteration();
      }
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
    p.building.wrapped = to_list(p.building.meshes);
    p.building.feature = p.feature ? py::object(feature_to_python(*p.feature)) : py::object(py::none());
    return py::cast(std::move(p.building));
  }

  // Stops the workers (buildings being evaluated are cancelled), joins them
  // and drops the spool. Idempotent; the destructor calls it.
  void close() {
    recipe_.options.cancel.cancel();
    if (!pipeline_) return;
    if (PyGILState_Check()) {
      py::gil_scoped_release release;
      pipeline_->close();
    } else {
      pipeline_->close();
    }
    spool_.reset();
  }

 private:
  struct Pending {
    Building building;                     // its Python members are made by next()
    std::optional<GeoJsonFeature> feature;  // as evaluated, for Building.feature
  };
  using Pipeline = OrderedPipeline<Pending>;

  // The i-th building as the workers take it: its feature back from the
  // spool (on the pipeline's thread, one at a time), or refused.
  Pending pending(std::size_t i) const {
    const FeatureSource& s = sources_[i];
    Pending p;
    p.building.index = s.index;
    if (!s.error) p.feature = spool_->at(s.spooled), p.building.id = p.feature->id;
    else p.building.id = s.error->id, p.building.status = "refused", p.building.reason = s.error->message;
    return p;
  }

  std::shared_ptr<Recipe> source_recipe_;
  MeshRecipe recipe_;
  std::optional<FeatureSpool> spool_;
  std::vector<GeoJsonFeatureError> errors_;  // what the unreadable footprints say, kept once
  std::vector<FeatureSource> sources_;
  // As batch(): nodes that do not depend on the building run once; the rest are never asked twice.
  ResultCache cache_{std::size_t{32} << 20};
  Evaluator evaluator_{cache_, kEngineSalt};
  PlaceableCache placeables_;
  tbb::task_arena arena_;
  std::optional<Pipeline> pipeline_;  // last: it stops before what it reads goes
};

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
  py::class_<BatchStream>(m, "BatchIterator",
                          "What batch_iter returns: the batch's buildings one at a time, in footprint order. "
                          "close() (or leaving a with block, or dropping it) stops the workers and removes the "
                          "footprints' temporary file.")
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", &BatchStream::next)
      .def("__len__", &BatchStream::size, "The number of buildings (footprints, readable or not).")
      .def("close", &BatchStream::close, "Stops evaluating: the workers are joined, the temporary file removed.")
      .def("__enter__", [](py::object self) { return self; })
      .def("__exit__", [](BatchStream& s, py::args) { s.close(); });
  m.def(
      "batch_iter",
      [](std::shared_ptr<Recipe> recipe, py::handle footprints, int jobs, py::handle attributes, py::handle streets) {
        return std::make_unique<BatchStream>(std::move(recipe), footprints, jobs, attributes, streets);
      },
      py::arg("recipe"), py::arg("footprints"), py::arg("jobs") = 0, py::arg("attributes") = py::none(),
      py::arg("streets") = py::none(),
      "batch() in bounded memory: an iterator over the same Buildings, in the same order, handed over one at a "
      "time. The footprints are set aside in a temporary file as procex batch keeps them (a file's path is read "
      "feature by feature, never whole), and the worker threads evaluate while the GIL is released, going on past a "
      "slow building while you wait for it, but at most 64 buildings per job ahead of it and 64 per job made "
      "and not yet handed over, so memory does not grow with the number of footprints as long as the caller "
      "does not keep the buildings. A footprint that cannot be read or a building that fails is a Building with "
      "that status; the rest go on. Arguments as batch(). Use it in a with block (or call close()) to stop early: "
      "dropping it does the same.");
}

}  // namespace procex::python
