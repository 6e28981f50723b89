// eval_worker.h -- evaluates the edited graph on a background thread.
//
// The UI submits a snapshot of the graph after every edit; a newer submission
// cancels the running evaluation. The last good preview mesh stays available
// while the next evaluation runs and when it fails, so the window never waits
// for an evaluation and an error never blanks the preview.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "app/studio/editor/preview_mesh.h"
#include "graph/cache.h"
#include "graph/evaluator.h"
#include "core/geom/footprint.h"
#include "core/io/geojson.h"
#include "graph/graph.h"
#include "nodes/values.h"

namespace procex::studio {

// The ports the preview shows: the sources of the connected graph outputs or,
// when no graph output is connected, every output of the nodes whose outputs
// feed nothing (the ends of the graph).
std::vector<PortRef> preview_ports(const Graph& g);

// Values for the graph inputs that have no default, so that a recipe made for
// batch runs (a footprint bound per feature) still shows something: a
// footprint input gets `footprint`, other unbound inputs stay unbound (and
// their users report it).
Bindings preview_bindings(const Graph& g, const Footprint& footprint);
// The stand-in plan for an unbound footprint input: a 14 m x 10 m rectangle, edges at 45 degrees.
Footprint preview_footprint();

// The features of a footprint file given to the preview (dropped on the
// window, or --footprints): the recipe is evaluated once per feature, each
// bound as procex batch binds it (app/cli/feature_binding.h: the plan at its
// real position, its id, its properties as settings), and the preview shows
// them all together.
using PreviewFeatures = std::shared_ptr<const std::vector<GeoJsonFeature>>;

struct EvalSnapshot {
  std::uint64_t revision = 0;    // the document revision this evaluation saw
  EvalResult result;             // diagnostics and per-node statistics
  std::map<PortRef, Value> values;  // every evaluated port (preview ports and extras)
  std::shared_ptr<const PreviewMesh> preview;  // the last good meshes, maybe of an earlier revision
  bool preview_current = false;  // whether `preview` comes from this revision
  double seconds = 0.0;          // evaluation plus preview building
  // With preview features: `result` and `values` are the first feature's
  // evaluation (what the canvas and the plan editor show), `result.diagnostics`
  // every feature's, each naming its feature; feature_meshes holds the meshes
  // of each feature that gave them all, labelled as procex batch labels them
  // (what File > Export writes), and `features` how many were evaluated.
  std::vector<MeshSet> feature_meshes;
  std::size_t features = 0;
};

// What `s` says of the graph inside group node `scope` (Document::scope):
// the statistics and diagnostics of the nodes in it, with paths relative to
// it, so the canvas marks an inner node as it marks a recipe's. Port values
// are left out: they are the recipe's ports.
EvalSnapshot inside_group(const EvalSnapshot& s, const NodePath& scope);

class EvalWorker {
 public:
  // `finished` is called on the evaluation thread each time an evaluation
  // ends (latest() has its result, or it was cancelled): the window wakes to
  // show it instead of polling the worker while it waits.
  explicit EvalWorker(std::function<void()> finished = {}, std::size_t cache_bytes = std::size_t{512} << 20);
  ~EvalWorker();
  EvalWorker(const EvalWorker&) = delete;
  EvalWorker& operator=(const EvalWorker&) = delete;

  // Evaluates `graph` (the preview ports plus `extra_ports`, e.g. the selected
  // node's outputs for the plan editor), cancelling whatever runs. Relative
  // file paths in parameters resolve against `folder` (the recipe's). With
  // `features`, the recipe is evaluated for each of them (see PreviewFeatures).
  void submit(std::uint64_t revision, Graph graph, std::vector<PortRef> extra_ports = {}, Bindings bindings = {},
              std::filesystem::path folder = {}, PreviewFeatures features = {});
  // The newest finished (not cancelled) evaluation, or null before the first.
  std::shared_ptr<const EvalSnapshot> latest() const;
  // Drops the pending evaluation and asks the running one to stop.
  void cancel();
  // Nothing pending or running.
  bool idle() const;
  // Waits until idle; false on timeout.
  bool wait_idle(std::chrono::milliseconds timeout) const;

 private:
  struct Job {
    std::uint64_t revision = 0;
    Graph graph;
    std::vector<PortRef> extra_ports;
    Bindings bindings;
    std::filesystem::path folder;
    PreviewFeatures features;
  };
  void run();
  std::shared_ptr<const EvalSnapshot> evaluate(Job& job, const CancelToken& cancel);
  std::shared_ptr<const EvalSnapshot> evaluate_features(Job& job, const CancelToken& cancel);
  // The preview of `meshes` into `snap` (`complete`: every preview port gave a value), else the last good one.
  void finish_preview(EvalSnapshot& snap, const std::vector<const TaggedMesh*>& meshes, bool complete);

  ResultCache cache_;
  Evaluator evaluator_;
  std::function<void()> finished_;
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::optional<Job> pending_;
  CancelToken running_cancel_;
  bool running_ = false, stop_ = false;
  std::shared_ptr<const EvalSnapshot> latest_;
  std::thread thread_;  // last: starts after every other member exists
};

}  // namespace procex::studio
