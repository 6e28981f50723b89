// The samples that place meshes at anchors (windows_grid, buttresses,
// pillars) evaluate to .glb files whose placed meshes are instanced nodes and
// that pass the Khronos glTF validator; windows_grid, its footprint bound by
// `procex batch`, puts its windows on every building of a block.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include "app/cli/batch_command.h"
#include "app/cli/eval_command.h"
#include "core/io/geojson.h"
#include "core/io/glb_read.h"
#include "core/io/gltf_write.h"
#include "graph/pxg.h"
#include "nodes/values.h"
#include "tests/app/command_test.h"
#include "tests/app/sample_block.h"
#include "tests/support/gltf_scripts.h"

namespace procex {
namespace {

namespace fs = std::filesystem;

const fs::path kSamples = PROCEX_SAMPLES;

using AnchoredSamples = test::CommandTest;

std::size_t instances_in(const GltfScene& scene) {
  std::size_t n = 0;
  for (const GltfMeshData& m : scene.meshes) n += m.instances.size();
  return n;
}

void expect_valid_gltf(const fs::path& glb) {
  const test::NodeScriptRun v = test::run_gltf_script("validate_gltf.mjs", glb);
  ASSERT_TRUE(v.problem.empty()) << v.problem;
  EXPECT_EQ(v.report["issues"]["numErrors"], 0) << v.report["issues"]["messages"].dump(1);
  EXPECT_EQ(v.report["issues"]["numWarnings"], 0) << v.report["issues"]["messages"].dump(1);
}

TEST_F(AnchoredSamples, EvaluateToValidGlbWithInstancedMeshes) {
  // The instances each sample places (its stored summary says the same).
  const std::pair<const char*, std::size_t> samples[] = {{"windows_grid", 28}, {"buttresses", 7}, {"pillars", 8}};
  for (const auto& [name, count] : samples) {
    SCOPED_TRACE(name);
    const fs::path glb = dir_ / (std::string(name) + ".glb");
    out_.str("");
    ASSERT_EQ(run_eval(test::eval_options(kSamples / (std::string(name) + ".pxg"), glb), out_, err_), 0) << err_.str();
    // The summary line counts what was placed, not only the building.
    EXPECT_NE(out_.str().find("1 meshes, "), std::string::npos) << out_.str();
    EXPECT_NE(out_.str().find(", " + std::to_string(count) + " placed meshes -> "), std::string::npos) << out_.str();
    const GltfScene scene = read_glb_scene(glb);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(instances_in(scene), count);
    EXPECT_EQ(scene.prototypes.size(), 1u);  // one placed mesh, shared by every instance
    expect_valid_gltf(glb);
  }
}

// windows_grid.pxg with its Footprint Polygon replaced by the graph input
// `footprint` that batch binds, saved beside the test's output (the mesh
// files then named by absolute path, in a folder the batch must allow).
fs::path batch_recipe(const fs::path& dir) {
  Graph g = load_pxg(kSamples / "windows_grid.pxg");
  NodeId polygon = 0, assign = 0;
  for (const auto& [id, n] : g.nodes()) {
    if (n.decl().type_name() == "Footprint Polygon") polygon = id;
    if (n.decl().type_name() == "Assign Profiles") assign = id;
    if (n.decl().type_name() == "Mesh Placement") {
      const std::size_t file = *n.decl().param_index("file");
      EXPECT_TRUE(g.set_param(id, file, Value::make((kSamples / n.params[file].get<std::string>()).string())));
    }
  }
  EXPECT_TRUE(g.remove_node(polygon));
  EXPECT_TRUE(g.add_input({"footprint", &value_type<Footprint>(), "bound by procex batch", {}}));
  EXPECT_TRUE(g.connect({kGraphInputs, static_cast<std::uint32_t>(*g.input_index("footprint"))}, {assign, 0}));
  const fs::path file = dir / "windows_batch.pxg";
  save_pxg(g, file);
  return file;
}

TEST_F(AnchoredSamples, BatchOfWindowsGridPlacesWindowsOnEveryBuilding) {
  BatchCommandOptions o;
  o.recipe = batch_recipe(dir_);
  o.footprints = test::kSampleBlock;
  o.output = dir_ / "block.glb";
  o.report = dir_ / "block.json";
  o.progress = false;
  o.jobs = 2;
  o.allowed_paths = {kSamples};
  ASSERT_EQ(run_batch(o, out_, err_), 0) << err_.str() << test::read_text(o.report);
  const GltfScene scene = read_glb_scene(o.output);
  const GeoJsonCollection block = read_geojson_file(o.footprints);
  ASSERT_EQ(scene.meshes.size(), block.features.size());
  for (std::size_t b = 0; b < scene.meshes.size(); ++b) {
    const GltfMeshData& building = scene.meshes[b];
    SCOPED_TRACE("building " + building.building);
    const GeoJsonFeature& f = block.features.at(static_cast<std::size_t>(building.feature));
    EXPECT_EQ(building.building, f.id);
    // The grid (untagged instances): two storeys, a window per 2.5 m of each
    // facade less 0.6 m at either end (the attic windows are tagged).
    std::size_t want = 0;
    for (const auto& loop : f.loops)
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const double length = glm::distance(loop[k], loop[(k + 1) % loop.size()]);
        want += 2 * static_cast<std::size_t>(std::max(0.0, std::floor((length - 1.2) / 2.5 + 1e-9)));
      }
    std::size_t grid = 0;
    for (const GltfInstanceData& in : building.instances) grid += in.tag.empty() ? 1 : 0;
    EXPECT_EQ(grid, want);
    EXPECT_GT(grid, 0u);
  }
  ASSERT_EQ(scene.prototypes.size(), 1u);
  EXPECT_EQ(scene.prototypes[0].building, "window");
  expect_valid_gltf(o.output);
}

}  // namespace
}  // namespace procex
