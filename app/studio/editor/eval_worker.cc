#include "app/studio/editor/eval_worker.h"

#include <algorithm>
#include <set>
#include <typeindex>

#include "app/cli/feature_binding.h"
#include "app/studio/editor/thread_cpu.h"
#include "nodes/support/mesh_labels.h"

namespace procex::studio {

std::vector<PortRef> preview_ports(const Graph& g) {
  std::vector<PortRef> ports;
  for (std::uint32_t i = 0; i < g.outputs().size(); ++i)
    if (auto from = g.source(PortRef{kGraphOutputs, i}); from && from->node != kGraphInputs) ports.push_back(*from);
  if (!ports.empty()) return ports;
  std::set<NodeId> feeding;
  for (const auto& [to, from] : g.links()) feeding.insert(from.node);
  for (const auto& [id, node] : g.nodes()) {
    if (feeding.count(id)) continue;
    for (std::uint32_t o = 0; o < node.decl().outputs().size(); ++o) ports.push_back(PortRef{id, o});
  }
  return ports;
}

Footprint preview_footprint() { return make_footprint({{{0, 0}, {14, 0}, {14, 10}, {0, 10}}}, 45.0); }

Bindings preview_bindings(const Graph& g, const Footprint& footprint) {
  Bindings b;
  for (const GraphInput& in : g.inputs())
    if (in.default_value.empty() && in.type && in.type->cpp_type() == std::type_index(typeid(Footprint))) b[in.name] = Value::make(footprint);
  return b;
}

EvalSnapshot inside_group(const EvalSnapshot& s, const NodePath& scope) {
  EvalSnapshot in;
  in.revision = s.revision;
  in.preview = s.preview;
  in.preview_current = s.preview_current;
  in.seconds = s.seconds;
  in.result.cancelled = s.result.cancelled;
  const auto inner = [&](const NodePath& p) { return p.size() > scope.size() && std::equal(scope.begin(), scope.end(), p.begin()); };
  const auto relative = [&](const NodePath& p) { return NodePath(p.begin() + static_cast<std::ptrdiff_t>(scope.size()), p.end()); };
  for (const NodeStats& n : s.result.stats.nodes)
    if (inner(n.path)) {
      in.result.stats.nodes.push_back(n);
      in.result.stats.nodes.back().path = relative(n.path);
    }
  for (const Diagnostic& d : s.result.diagnostics)
    if (inner(d.node)) {
      in.result.diagnostics.push_back(d);
      in.result.diagnostics.back().node = relative(d.node);
    }
  return in;
}

EvalWorker::EvalWorker(std::function<void()> finished, std::size_t cache_bytes)
    : cache_(cache_bytes), evaluator_(cache_, "procex-studio"), finished_(std::move(finished)), thread_([this] { run(); }) {}

EvalWorker::~EvalWorker() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    running_cancel_.cancel();
  }
  changed_.notify_all();
  thread_.join();
}

void EvalWorker::submit(std::uint64_t revision, Graph graph, std::vector<PortRef> extra_ports, Bindings bindings,
                        std::filesystem::path folder, PreviewFeatures features) {
  {
    std::lock_guard lock(mutex_);
    pending_ = Job{revision, std::move(graph), std::move(extra_ports), std::move(bindings), std::move(folder), std::move(features)};
    running_cancel_.cancel();
  }
  changed_.notify_all();
}

void EvalWorker::cancel() {
  {
    std::lock_guard lock(mutex_);
    pending_.reset();
    running_cancel_.cancel();
  }
  changed_.notify_all();
}

std::shared_ptr<const EvalSnapshot> EvalWorker::latest() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

bool EvalWorker::idle() const {
  std::lock_guard lock(mutex_);
  return !pending_ && !running_;
}

bool EvalWorker::wait_idle(std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return changed_.wait_for(lock, timeout, [this] { return !pending_ && !running_; });
}

void EvalWorker::run() {
  name_this_thread("procex-eval");  // apart from the UI thread in top, perf and the frame report
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [this] { return stop_ || pending_; });
    if (stop_) return;
    Job job = std::move(*pending_);
    pending_.reset();
    running_cancel_ = CancelToken();
    const CancelToken cancel = running_cancel_;
    running_ = true;
    lock.unlock();
    std::shared_ptr<const EvalSnapshot> snapshot = evaluate(job, cancel);
    lock.lock();
    if (snapshot) latest_ = std::move(snapshot);
    running_ = false;
    changed_.notify_all();
    if (finished_) {
      lock.unlock();
      finished_();
      lock.lock();
    }
  }
}

std::shared_ptr<const EvalSnapshot> EvalWorker::evaluate(Job& job, const CancelToken& cancel) {
  if (job.features && !job.features->empty()) return evaluate_features(job, cancel);
  const auto start = std::chrono::steady_clock::now();
  std::vector<PortRef> ports = preview_ports(job.graph);
  const std::size_t n_preview = ports.size();
  ports.insert(ports.end(), job.extra_ports.begin(), job.extra_ports.end());
  auto snap = std::make_shared<EvalSnapshot>();
  snap->revision = job.revision;
  EvalOptions options;
  options.cancel = cancel;
  options.folder = job.folder;
  snap->result = evaluator_.evaluate_ports(job.graph, job.bindings, ports, options);
  if (snap->result.cancelled || cancel.cancelled()) return nullptr;

  std::vector<const TaggedMesh*> meshes;
  bool complete = true;
  for (std::size_t i = 0; i < ports.size(); ++i) {
    const Value v = i < snap->result.outputs.size() ? snap->result.outputs[i].value : Value();
    if (!v.empty()) snap->values[ports[i]] = v;
    if (i >= n_preview) continue;
    if (v.empty()) complete = false;
    for (const TaggedMesh* m : meshes_in(v)) meshes.push_back(m);
  }
  finish_preview(*snap, meshes, complete);
  snap->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return snap;
}

std::shared_ptr<const EvalSnapshot> EvalWorker::evaluate_features(Job& job, const CancelToken& cancel) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<PortRef> preview = preview_ports(job.graph);
  std::vector<PortRef> first_ports = preview;  // the selected node's outputs: of the first feature only
  first_ports.insert(first_ports.end(), job.extra_ports.begin(), job.extra_ports.end());
  auto snap = std::make_shared<EvalSnapshot>();
  snap->revision = job.revision;
  // As procex batch does, a feature refused or failed is reported (by its id) and the others are
  // shown; only when none gives its meshes does the preview keep the last good one.
  bool any_complete = false;
  for (const GeoJsonFeature& f : *job.features) {
    const bool first = snap->features == 0;  // the first feature evaluated
    Graph graph = job.graph;
    Bindings bindings = job.bindings;
    EvalOptions options;
    options.cancel = cancel;
    options.folder = job.folder;
    const std::vector<std::string> problems = bind_feature(graph, bindings, options, f);
    for (const std::string& p : problems) snap->result.diagnostics.push_back({Severity::kError, {}, "", "feature " + f.id + ": " + p});
    if (!problems.empty()) continue;
    const std::vector<PortRef>& ports = first ? first_ports : preview;
    EvalResult r = evaluator_.evaluate_ports(graph, bindings, ports, options);
    if (r.cancelled || cancel.cancelled()) return nullptr;
    ++snap->features;
    for (Diagnostic& d : r.diagnostics) {
      d.message = "feature " + f.id + ": " + d.message;
      snap->result.diagnostics.push_back(std::move(d));
    }
    MeshSet meshes;
    bool complete = true;
    for (std::size_t i = 0; i < ports.size(); ++i) {
      const Value v = i < r.outputs.size() ? r.outputs[i].value : Value();
      if (first && !v.empty()) snap->values[ports[i]] = v;
      if (i >= preview.size()) continue;
      if (v.empty()) complete = false;
      if (const MeshSet* m = v.get_if<MeshSet>()) meshes.parts.insert(meshes.parts.end(), m->parts.begin(), m->parts.end());
    }
    if (first) {
      snap->result.stats = std::move(r.stats);
      snap->result.outputs = std::move(r.outputs);
    }
    if (!complete) continue;
    any_complete = true;
    label_parts(meshes, f);
    snap->feature_meshes.push_back(std::move(meshes));
  }
  std::vector<const TaggedMesh*> meshes;
  for (const MeshSet& set : snap->feature_meshes)
    for (const TaggedMesh& part : set.parts)
      if (part.mesh) meshes.push_back(&part);
  finish_preview(*snap, meshes, any_complete);
  snap->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return snap;
}

void EvalWorker::finish_preview(EvalSnapshot& snap, const std::vector<const TaggedMesh*>& meshes, bool complete) {
  if (complete && !meshes.empty()) {
    snap.preview = std::make_shared<const PreviewMesh>(make_preview(meshes));
    snap.preview_current = true;
  } else if (complete) {
    snap.preview_current = true;  // a good result without meshes: nothing to show
  } else {
    std::lock_guard lock(mutex_);
    if (latest_) snap.preview = latest_->preview;
  }
}

}  // namespace procex::studio
