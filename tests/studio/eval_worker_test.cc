// The background evaluation: results arrive without blocking, a newer
// submission cancels an older one, and a failing edit keeps the last good mesh.
#include "app/studio/editor/eval_worker.h"

#include <gtest/gtest.h>

#include <mutex>
#include <thread>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include "app/studio/editor/document.h"
#include "app/cli/feature_binding.h"
#include "core/io/footprint_read.h"
#include "graph/pxg.h"
#include "tests/studio/studio_test_util.h"

namespace procex::studio {
namespace {

using namespace std::chrono_literals;

TEST(PreviewPorts, GraphOutputsFirstElseTheEndsOfTheGraph) {
  Document doc;
  NodeId c = *doc.add_node("test.Const", 0, 0);
  NodeId add = *doc.add_node("test.Add", 0, 0);
  ASSERT_TRUE(doc.connect({c, 0}, {add, 0}));
  EXPECT_EQ(preview_ports(doc.graph()), (std::vector<PortRef>{{add, 0}}));
  const Graph house = load_pxg(test::house_recipe());
  EXPECT_EQ(preview_ports(house), (std::vector<PortRef>{{2, 0}}));
}

TEST(EvalWorker, EvaluatesTheHouseIntoATaggedPreview) {
  EvalWorker worker;
  const Graph g = load_pxg(test::house_recipe());
  worker.submit(1, g);
  ASSERT_TRUE(worker.wait_idle(60s));
  auto snap = worker.latest();
  ASSERT_TRUE(snap);
  EXPECT_EQ(snap->revision, 1u);
  EXPECT_TRUE(snap->result.ok());
  ASSERT_TRUE(snap->preview);
  EXPECT_TRUE(snap->preview_current);
  EXPECT_EQ(snap->preview->meshes, 1u);
  EXPECT_GT(snap->preview->faces, 5u);
  EXPECT_TRUE(snap->preview->tag("roof"));
  EXPECT_EQ(snap->result.stats.computed(), 2u);
  // The same graph again: everything from the cache.
  worker.submit(2, g);
  ASSERT_TRUE(worker.wait_idle(60s));
  EXPECT_EQ(worker.latest()->result.stats.computed(), 0u);
  EXPECT_EQ(worker.latest()->result.stats.count(NodeOutcome::kCacheHit), 1u);
}

TEST(EvalWorker, FailedEvaluationKeepsTheLastGoodMesh) {
  EvalWorker worker;
  auto doc = Document::open(test::house_recipe());
  worker.submit(doc->revision(), doc->graph());
  ASSERT_TRUE(worker.wait_idle(60s));
  auto good = worker.latest()->preview;
  ASSERT_TRUE(good);
  // Disconnecting the footprint makes Extrude fail (a required input).
  ASSERT_TRUE(doc->disconnect({2, 0}));
  worker.submit(doc->revision(), doc->graph());
  ASSERT_TRUE(worker.wait_idle(60s));
  auto snap = worker.latest();
  EXPECT_EQ(snap->revision, doc->revision());
  EXPECT_TRUE(snap->result.has_errors());
  EXPECT_EQ(snap->preview, good);
  EXPECT_FALSE(snap->preview_current);
}

TEST(EvalWorker, NewerSubmissionCancelsTheRunningOne) {
  EvalWorker worker;
  Document doc;
  NodeId c = *doc.add_node("test.Const", 0, 0);
  NodeId slow = *doc.add_node("test.Slow", 0, 0);
  ASSERT_TRUE(doc.connect({c, 0}, {slow, 0}));
  ASSERT_TRUE(doc.set_param(slow, 0, Value::make<std::int64_t>(60000)));  // a minute, unless cancelled
  worker.submit(1, doc.graph());
  ASSERT_TRUE(doc.set_param(slow, 0, Value::make<std::int64_t>(1)));
  worker.submit(2, doc.graph());
  ASSERT_TRUE(worker.wait_idle(30s));
  ASSERT_TRUE(worker.latest());
  EXPECT_EQ(worker.latest()->revision, 2u);  // the cancelled evaluation never shows
  EXPECT_TRUE(worker.latest()->result.ok());
}

// The window sleeps until the worker wakes it: by then the result must be there to take.
TEST(EvalWorker, FinishedIsCalledWithTheResultInPlace) {
  std::mutex m;
  std::vector<std::uint64_t> seen;  // latest()'s revision at each call
  EvalWorker* self = nullptr;
  EvalWorker worker([&] {
    std::lock_guard lock(m);
    seen.push_back(self->latest() ? self->latest()->revision : 0);
  });
  self = &worker;
  const Graph g = load_pxg(test::house_recipe());
  worker.submit(7, g);
  ASSERT_TRUE(worker.wait_idle(60s));
  // wait_idle returns when the evaluation is marked done, just before the call.
  for (int i = 0; i < 6000; ++i) {
    std::lock_guard lock(m);
    if (!seen.empty()) break;
    std::this_thread::sleep_for(10ms);
  }
  std::lock_guard lock(m);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0], 7u);
}

TEST(EvalWorker, ExtraPortsAreEvaluatedToo) {
  EvalWorker worker;
  const Graph g = load_pxg(test::house_recipe());
  worker.submit(1, g, {PortRef{1, 0}});
  ASSERT_TRUE(worker.wait_idle(60s));
  EXPECT_TRUE(worker.latest()->values.count(PortRef{1, 0}));
  EXPECT_TRUE(worker.latest()->values.count(PortRef{2, 0}));
}

}  // namespace
}  // namespace procex::studio

namespace procex::studio {
namespace {

TEST(PreviewBindings, UnboundFootprintInputsGetTheStandInPlan) {
  Graph g;
  ASSERT_TRUE(g.add_input({"footprint", &value_type<Footprint>(), "", {}}));
  ASSERT_TRUE(g.add_input({"seed", &value_type<std::int64_t>(), "", {}}));
  ASSERT_TRUE(g.add_input({"other", &value_type<Footprint>(), "", Value::make(preview_footprint())}));
  const Bindings b = preview_bindings(g, preview_footprint());
  ASSERT_EQ(b.size(), 1u);
  ASSERT_TRUE(b.count("footprint"));
  EXPECT_EQ(b.at("footprint").get<Footprint>().loops.at(0).points.size(), 4u);
}

TEST(EvalWorker, BatchRecipeShowsTheStandInPlan) {
  const Graph city = load_pxg(std::filesystem::path(PROCEX_SAMPLES) / "city.pxg");
  auto worker = std::make_unique<EvalWorker>();
  // The recipe's folder: its windows and doors are meshes beside it.
  worker->submit(1, city, {}, preview_bindings(city, preview_footprint()), PROCEX_SAMPLES);
  if (!worker->wait_idle(std::chrono::seconds(60))) {
    // A node that never returns cannot be joined: leave its thread be, fail.
    (void)worker.release();
    FAIL() << "the city recipe on the stand-in plan did not evaluate within 60 s";
  }
  EXPECT_TRUE(worker->latest()->result.ok());
  ASSERT_TRUE(worker->latest()->preview);
  EXPECT_GT(worker->latest()->preview->faces, 4u);
}

// A footprint file given to the preview: the recipe evaluated for every
// feature, bound as procex batch binds it, each building where its feature
// stands; an edit evaluates again only what it changed; a feature that cannot
// be bound is named and the others still shown.
TEST(EvalWorker, EveryFeatureOfAFootprintFileAtItsPlace) {
  const std::filesystem::path samples = PROCEX_SAMPLES;
  const Graph city = load_pxg(samples / "city.pxg");
  GeoJsonCollection block = read_footprints(samples / "footprints" / "sample_block.geojson");
  ASSERT_EQ(block.features.size(), 18u);
  add_edge_labels(city, block);
  glm::dvec2 lo(1e300), hi(-1e300);
  for (const GeoJsonFeature& f : block.features)
    for (const auto& loop : f.loops)
      for (const glm::dvec2& p : loop) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
  const auto features = std::make_shared<const std::vector<GeoJsonFeature>>(block.features);
  EvalWorker worker;
  worker.submit(1, city, {}, preview_bindings(city, preview_footprint()), samples, features);
  ASSERT_TRUE(worker.wait_idle(120s));
  auto snap = worker.latest();
  ASSERT_TRUE(snap && snap->preview);
  EXPECT_EQ(snap->features, 18u);
  EXPECT_EQ(snap->feature_meshes.size(), 18u);
  for (const Diagnostic& d : snap->result.diagnostics) EXPECT_NE(d.severity, Severity::kError) << d.to_string();
  EXPECT_TRUE(snap->preview_current);
  // The preview spans the block: every plan at its own place, none at the origin of its own.
  const PreviewMesh& p = *snap->preview;
  EXPECT_NEAR(p.min.x, lo.x, 1e-3);
  EXPECT_NEAR(p.min.y, lo.y, 1e-3);
  EXPECT_NEAR(p.max.x, hi.x, 1e-3);
  EXPECT_NEAR(p.max.y, hi.y, 1e-3);
  EXPECT_GT(p.max.z, 3.0) << "buildings, not plans";
  EXPECT_GE(p.meshes, 18u);

  // Submitted again unchanged: every feature's buildings come from the cache.
  worker.submit(2, city, {}, preview_bindings(city, preview_footprint()), samples, features);
  ASSERT_TRUE(worker.wait_idle(120s));
  EXPECT_EQ(worker.latest()->result.stats.computed(), 0u) << "an unchanged recipe comes from the cache";
  EXPECT_EQ(worker.latest()->features, 18u);

  // A bow-tie among them is refused, by its id, as procex batch refuses it; the rest are shown.
  std::vector<GeoJsonFeature> with_bad = block.features;
  GeoJsonFeature bad = with_bad.front();
  bad.id = "bow-tie";
  bad.loops = {{{0, 0}, {10, 10}, {10, 0}, {0, 10}}};
  with_bad.push_back(bad);
  worker.submit(3, city, {}, preview_bindings(city, preview_footprint()), samples,
                std::make_shared<const std::vector<GeoJsonFeature>>(with_bad));
  ASSERT_TRUE(worker.wait_idle(120s));
  snap = worker.latest();
  EXPECT_EQ(snap->feature_meshes.size(), 18u);
  ASSERT_TRUE(snap->preview_current);
  bool named = false;
  for (const Diagnostic& d : snap->result.diagnostics) named |= d.severity == Severity::kError && d.message.starts_with("feature bow-tie: ");
  EXPECT_TRUE(named) << "the refused feature is named";
}

}  // namespace
}  // namespace procex::studio
